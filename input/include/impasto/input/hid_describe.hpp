#pragma once
// Human-readable summaries of a report descriptor and of a tablet's pen, for `impasto hid`.
#include <impasto/input/hid_descriptor.hpp>
#include <impasto/input/hid_device.hpp>
#include <impasto/input/hid_pen.hpp>

#include <string>

namespace impasto::input::hid {

// Every report with its size and fields: bit position, size x count, usages, extents, unit.
std::string describe_reports(const ReportDescriptor& descriptor);

// The pen's axes and ranges: position extents in mm, pressure levels, tilt and twist.
std::string describe_pen(const PenDecoder& decoder);

// `impasto hid list`: per tablet its node, ids and name, then vendor, model, protocol, area
// in mm, pressure levels and tilt, or why it is unsupported.
std::string describe_tablet_list(const std::vector<PenTabletInfo>& tablets);

}  // namespace impasto::input::hid
