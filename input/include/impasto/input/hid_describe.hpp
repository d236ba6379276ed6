#pragma once
// Human-readable summaries of a report descriptor and of a tablet's pen, for `impasto hid`.
#include <impasto/input/hid_descriptor.hpp>
#include <impasto/input/hid_pen.hpp>

#include <string>

namespace impasto::input::hid {

// Every report with its size and fields: bit position, size x count, usages, extents, unit.
std::string describe_reports(const ReportDescriptor& descriptor);

// The pen's axes and ranges: position extents in mm, pressure levels, tilt and twist.
std::string describe_pen(const PenDecoder& decoder);

}  // namespace impasto::input::hid
