#include "impasto/files/message_text.hpp"

#include <gtest/gtest.h>

namespace impasto::files {
namespace {

TEST(MessageText, QuotesShortTextAsItIs) {
  EXPECT_EQ(excerpt("White"), "'White'");
}

TEST(MessageText, EscapesControlCharacters) {
  EXPECT_EQ(excerpt("a\x1b[31mred\n\t\\"), "'a\\x1b[31mred\\n\\t\\\\'");
  EXPECT_EQ(excerpt(std::string("\0\x7f", 2)), "'\\x00\\x7f'");
}

// Names printed to a terminal: an escape code cannot reach it; a message's own lines stay.
TEST(MessageText, TerminalTextEscapesControlCharactersButAMessagesLines) {
  EXPECT_EQ(terminal_text("red \x1b[31m name\n"), "red \\x1b[31m name\\n");
  EXPECT_EQ(terminal_text("a.strokes:3: bad\n  see docs", true), "a.strokes:3: bad\n  see docs");
  EXPECT_EQ(terminal_text("bell\a\x7f", true), "bell\\x07\\x7f");
  EXPECT_EQ(terminal_text("C:\\path"), "C:\\path");
}

TEST(MessageText, CutsLongText) {
  const std::string long_text(60'000'000, 'x');
  const std::string q = excerpt(long_text);
  EXPECT_EQ(q, "'" + std::string(kQuotedChars, 'x') + "'... (60000000 bytes)");
}

TEST(MessageText, DescribesSizes) {
  EXPECT_EQ(describe_bytes(193), "193 bytes");
  EXPECT_EQ(describe_bytes(34'000'000'000ull), "34.0 GB");
  EXPECT_EQ(describe_bytes(671'000'000), "671.0 MB");
}

}  // namespace
}  // namespace impasto::files
