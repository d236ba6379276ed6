#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "impasto/util/enum_names.hpp"
#include "impasto/util/fnv1a.hpp"
#include "impasto/util/statistics.hpp"
#include "impasto/util/text.hpp"

namespace impasto::util {
namespace {

TEST(Trim, DropsBlanksAtBothEndsOnly) {
  EXPECT_EQ(trim("  a b\t\r"), "a b");
  EXPECT_EQ(trim("a"), "a");
  EXPECT_EQ(trim(" \t\r "), "");
  EXPECT_EQ(trim(""), "");
  EXPECT_EQ(trim("\na\n"), "\na\n");  // a newline is not a blank: lines are split first
}

TEST(KeyValueField, FindsTheFirstLineWithTheKey) {
  const std::string text = "# nk_table = no\n\nname = Gold \n nk_table =  gold.csv\r\nnk_table = b";
  EXPECT_EQ(key_value_field(text, "nk_table"), "gold.csv");
  EXPECT_EQ(key_value_field(text, "name"), "Gold");
  EXPECT_EQ(key_value_field(text, "missing"), "");
  EXPECT_EQ(key_value_field("key = last line without a newline", "key"),
            "last line without a newline");
}

TEST(LineEncoding, AnyNameRoundTripsOnOneLine) {
  std::string every_byte;
  for (int c = 1; c < 256; ++c) every_byte += static_cast<char>(c);
  for (const std::string& name : {std::string("/home/a b/50% grey.impasto"),
                                  std::string("line\nbreak\ttab\r"), every_byte, std::string()}) {
    const std::string line = line_encoded(name);
    EXPECT_EQ(line.find_first_of(std::string("\n\r\x7f", 3)), std::string::npos);
    EXPECT_EQ(line_decoded(line), name);
  }
  EXPECT_EQ(line_encoded("50%\n"), "50%25%0A");
  EXPECT_EQ(line_decoded("%0a%0A"), "\n\n");  // either case of hex digit
}

TEST(LineEncoding, APercentWithoutTwoHexDigitsStandsForItself) {
  // A hand-edited or torn line decodes to what it says and never throws (the session
  // registry's own decoder read "%zz" with std::stoi, which threw).
  EXPECT_EQ(line_decoded("%zz"), "%zz");
  EXPECT_EQ(line_decoded("%4z%"), "%4z%");
  EXPECT_EQ(line_decoded("a%4"), "a%4");
  EXPECT_EQ(line_decoded("%%41"), "%A");
}

TEST(Fnv1a, MatchesThePublishedTestVectors) {
  // From the FNV reference (isthe.com/chongo/tech/comp/fnv): "" and "a", 64-bit FNV-1a.
  EXPECT_EQ(fnv1a(""), 0xcbf29ce484222325ull);
  EXPECT_EQ(fnv1a("a"), 0xaf63dc4c8601ec8cull);
  EXPECT_EQ(fnv1a("foobar"), 0x85944171f73967e8ull);
}

TEST(Fnv1a, PiecesHashAsTheWhole) {
  const std::string text = "impasto";
  Fnv1a pieces;
  pieces.add(text.data(), 3);
  pieces.add(text.data() + 3, text.size() - 3);
  EXPECT_EQ(pieces.value(), fnv1a(text));
}

TEST(Median, OddAndEvenCounts) {
  EXPECT_DOUBLE_EQ(median({5.0, 1.0, 3.0}), 3.0);
  EXPECT_DOUBLE_EQ(median({4.0, 1.0, 3.0, 2.0}), 2.5);
  EXPECT_DOUBLE_EQ(median({7.0}), 7.0);
  EXPECT_THROW(median({}), std::invalid_argument);
}

enum class Fruit { apple, pear, plum };
constexpr EnumNames<Fruit, 3> kFruitNames{
    {{Fruit::apple, "apple"}, {Fruit::pear, "pear"}, {Fruit::plum, "plum"}}};

TEST(EnumNames, ParsesNamesAndListsThemInOrder) {
  EXPECT_EQ(parse_name(kFruitNames, "pear", "fruit"), Fruit::pear);
  EXPECT_EQ(name_of(kFruitNames, Fruit::plum), "plum");
  EXPECT_EQ(names_of(kFruitNames), (std::vector<std::string>{"apple", "pear", "plum"}));
  EXPECT_EQ(names_text(kFruitNames), "apple, pear or plum");
}

TEST(EnumNames, AnUnknownNameIsAnErrorListingTheChoices) {
  try {
    parse_name(kFruitNames, "fig", "fruit");
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "unknown fruit 'fig' (expected apple, pear or plum)");
  }
}

}  // namespace
}  // namespace impasto::util
