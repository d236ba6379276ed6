#pragma once
// One line of a stroke file <-> one event. The reader and the writer share these, so that
// anything the writer emits is checked by the same rules the reader applies.
#include <impasto/input/stroke_events.hpp>

#include <string>
#include <string_view>
#include <vector>

#include "text_fields.hpp"

namespace impasto::input::detail {

// Parses the fields of one record line (not the header). Throws InputFormatError.
StrokeEvent parse_record(const std::vector<std::string_view>& fields, const LineContext& where);

// The record line of an event, without the newline.
std::string record_line(const StrokeEvent& event);

}  // namespace impasto::input::detail
