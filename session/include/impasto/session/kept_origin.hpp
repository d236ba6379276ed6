#pragma once
// The painting a session began from, kept beside its recording. Saving over that painting (or
// over the recovery autosave a recovered session began from) replaces the file, so the state
// the recording's `from` record names would be gone; the time-lapse shows the session's
// strokes over it, and a rebuild may need it. Kept as a second name of the same file (a hard
// link: no bytes are copied, and saves replace a file rather than rewrite it, so the link keeps
// the old state), or as a copy where a link cannot be made (another file system).
#include <impasto/input/stroke_events.hpp>
#include <impasto/paintcore/painting.hpp>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace impasto::session {

// How many of a painting's sessions in one folder keep their origin: the newest (keep_origin
// removes older ones' as it keeps a new one).
inline constexpr std::size_t kKeptOrigins = 8;

// Where the origin of the session recorded at `recording` is kept: "NAME.strokes" keeps it as
// "NAME.origin" (not ".impasto", so that it is not listed among the paintings beside it).
std::filesystem::path kept_origin_path(const std::filesystem::path& recording);

// Keeps `painting`, the file a session recorded at `recording` began from (symlinks followed;
// never written through a file or link already at the kept path), then removes the origins of
// the same painting's sessions in that folder beyond the newest kKeptOrigins. Returns why it
// could not keep it, or "" when kept.
std::string keep_origin(const std::filesystem::path& painting,
                        const std::filesystem::path& recording);

// The files that may hold the state a recording's `from` record names, in the order to try:
// the painting it names, then the copy kept beside the recording (file.source). Empty for a
// session begun on a new canvas.
struct OriginCandidates {
  std::vector<std::filesystem::path> files;
  std::uint64_t state_hash = 0;
  std::string where;  // the `from` record's "FILE:LINE"
};
OriginCandidates origin_candidates(const input::StrokeFile& file);

// The painting the recorded session began from, as it was then: the first candidate that loads
// with the state hash the `from` record names. None for a new canvas, and none (with a warning
// in `warnings`) when no candidate holds that state any more.
std::optional<paintcore::Painting> load_session_origin(const input::StrokeFile& file, int threads,
                                                       std::vector<std::string>& warnings);

}  // namespace impasto::session
