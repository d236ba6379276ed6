// `impasto hid describe/decode` on what tablet owners send: usbhid-dump streams and hex
// descriptors of a real Huion H610, with and without its ids and handshake; the formats
// found are named; bad ids are refused by name.
#include <gtest/gtest.h>

#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "command_line.hpp"

namespace impasto::app {
namespace {

const std::string kH610 = std::string(IMPASTO_TEST_FILES_DIR) + "/hid/captures/Huion_H610/";

struct Output {
  std::string out;
  std::string err;
};

Output run(const std::string& args) {
  testing::internal::CaptureStdout();
  testing::internal::CaptureStderr();
  try {
    run_command_in_process(args);
  } catch (...) {
    (void)testing::internal::GetCapturedStdout();
    (void)testing::internal::GetCapturedStderr();
    throw;
  }
  return {testing::internal::GetCapturedStdout(), testing::internal::GetCapturedStderr()};
}

std::vector<std::vector<std::string>> tsv_rows(const std::string& text) {
  std::vector<std::vector<std::string>> rows;
  std::istringstream lines(text);
  std::string line;
  while (std::getline(lines, line)) {
    std::vector<std::string> fields;
    std::istringstream cells(line);
    std::string cell;
    while (std::getline(cells, cell, '\t')) fields.push_back(cell);
    rows.push_back(fields);
  }
  return rows;
}

TEST(HidCommand, DecodesAUsbhidDumpStreamInMillimetres) {
  const Output o = run("hid decode --descriptor " + kH610 + "rd/original0.txt --reports " + kH610 +
                       "dumps/pen_coords.txt --id 256c:006e --strings " + kH610 + "probe.txt");
  EXPECT_NE(o.err.find("original0.txt: hex text"), std::string::npos) << o.err;
  EXPECT_NE(o.err.find("pen_coords.txt: usbhid-dump output, 1010 reports"), std::string::npos)
      << o.err;
  EXPECT_NE(o.err.find("Huion H610: protocol UC-Logic v1 (handshake)"), std::string::npos) << o.err;
  const auto rows = tsv_rows(o.out);
  ASSERT_EQ(rows.size(), 1u + 1010u);
  EXPECT_EQ(rows[0][0], "time");
  // The first report: 09 00 33 04 39 03 00 00 -> x 1075, y 825 of 2048.
  EXPECT_EQ(rows[1][1], "133.3252");  // 1075 / 2048 * 254
  EXPECT_EQ(rows[1][2], "63.9496");   // 825 / 2048 * 158.75
  // Without ids or handshake, the descriptor's own report 7 gives the same area.
  const Output bare = run("hid decode --descriptor " + kH610 + "rd/original0.txt --reports " +
                          kH610 + "dumps/pen_coords.txt");
  EXPECT_EQ(tsv_rows(bare.out), rows);
}

TEST(HidCommand, DescribeNamesTheFormatAndThePen) {
  const Output o = run("hid describe " + kH610 + "rd/original0.txt --id 256c:006e");
  EXPECT_NE(o.out.find("rd/original0.txt: hex text, 179 bytes"), std::string::npos) << o.out;
  EXPECT_NE(o.out.find("pen report 9 (8 bytes, outside a pen collection)"), std::string::npos)
      << o.out;
  EXPECT_NE(o.out.find("Huion / Gaomon, Huion H610"), std::string::npos) << o.out;
}

TEST(HidCommand, BadIdsAndFilesAreRefusedByName) {
  try {
    run("hid decode --descriptor " + kH610 + "rd/original0.txt --reports " + kH610 +
        "dumps/pen_coords.txt --id huion");
    FAIL() << "accepted a bad --id";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("--id: expected VID:PID in hex"), std::string::npos)
        << e.what();
  }
  try {
    run("hid describe " + kH610 + "probe.txt");
    FAIL() << "read string descriptors as a report descriptor";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("string descriptors, not a report descriptor"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace impasto::app
