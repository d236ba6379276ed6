#pragma once
// What a painting carries of each pigment it uses (paintcore::Painting::pigment_records,
// docs/painting-format.md): the pigment file's text (K, S, grid, metadata), then for a flake
// pigment its flake file and that file's n,k table, each after a line
// "#impasto-record-file NAME". A painting then renders the same without the library and after
// the library's version of a pigment changes.
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "impasto/data/pigments.hpp"
#include "impasto/paintcore/painting.hpp"

namespace impasto::render {

// The record of a pigment (its flake files read now). Throws naming an unreadable flake file.
std::string pigment_record(const data::Pigment& pigment);
// The pigment back from a record. A flake pigment's files are written to a folder of the
// user's cache named by the record's hash (the flake renderer reads files), and
// Pigment::flakes names the copy there. Throws naming `where` and the pigment.
data::Pigment pigment_from_record(const std::string& record, const std::string& where);

// The pigments a painting carries, parsed (an unreadable record fails naming the pigment).
std::shared_ptr<const std::map<std::string, data::Pigment>> carried_pigments(
    const paintcore::Painting& painting);

// Makes new paintings carry the active library's version of each pigment they take up, with
// the ground's white (Painting::set_pigment_record_source). Idempotent.
void install_pigment_records();

// The pigments whose carried record differs from the library's (or that the library lacks).
struct PigmentDrift {
  std::string name;
  bool missing_from_library = false;
};
std::vector<PigmentDrift> pigments_differing_from_library(const paintcore::Painting& painting);
// Replaces the carried records of `names` by the library's (the painting then renders with
// the library's pigments). Throws for a name the library lacks.
void use_library_pigments(paintcore::Painting& painting, const std::vector<std::string>& names);

}  // namespace impasto::render
