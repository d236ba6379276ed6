// The program's terms as a redistributor reads them: LICENSE holds the Apache License 2.0,
// packaging/copyright is well-formed Debian copyright format 1.0 that gives Impasto's own
// files that licence and names a licence for every other stanza, each stanza's patterns match
// files that exist, and NOTICE credits every third-party file the copyright file names.
#include <fnmatch.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

const fs::path kSource = IMPASTO_SOURCE_DIR;

std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// One paragraph of the copyright file: its fields, continuation lines joined by '\n'.
using Paragraph = std::map<std::string, std::string>;

std::vector<Paragraph> paragraphs_of(const std::string& text) {
  std::vector<Paragraph> paragraphs(1);
  std::string field;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    if (line.empty()) {
      if (!paragraphs.back().empty()) paragraphs.emplace_back();
      field.clear();
    } else if (line[0] == ' ' || line[0] == '\t') {
      EXPECT_FALSE(field.empty()) << "a continuation line outside a field: " << line;
      paragraphs.back()[field] += "\n" + line.substr(1);
    } else {
      const auto colon = line.find(':');
      EXPECT_NE(colon, std::string::npos) << "not a field: " << line;
      if (colon == std::string::npos) continue;
      field = line.substr(0, colon);
      std::string value = line.substr(colon + 1);
      if (!value.empty() && value[0] == ' ') value.erase(0, 1);
      EXPECT_EQ(paragraphs.back().count(field), 0u) << "field " << field << " twice";
      paragraphs.back()[field] = value;
    }
  }
  if (paragraphs.back().empty()) paragraphs.pop_back();
  return paragraphs;
}

std::vector<std::string> words_of(const std::string& text) {
  std::vector<std::string> words;
  std::istringstream in(text);
  for (std::string word; in >> word;) words.push_back(word);
  return words;
}

std::string first_line(const std::string& text) {
  return text.substr(0, text.find('\n'));
}

// The source tree's files, relative to its root, with the build folders left out.
std::vector<std::string> source_files() {
  std::vector<std::string> files;
  for (auto it = fs::recursive_directory_iterator(kSource);
       it != fs::recursive_directory_iterator(); ++it) {
    const std::string name = it->path().filename().string();
    if (it->is_directory() && (name == "build" || name == ".git")) {
      it.disable_recursion_pending();
      continue;
    }
    if (it->is_regular_file()) files.push_back(fs::relative(it->path(), kSource).string());
  }
  return files;
}

TEST(Licence, TheLicenceFileHoldsTheApacheLicence) {
  const std::string text = read_text(kSource / "LICENSE");
  EXPECT_NE(text.find("Apache License"), std::string::npos);
  EXPECT_NE(text.find("Version 2.0, January 2004"), std::string::npos);
  EXPECT_NE(text.find("END OF TERMS AND CONDITIONS"), std::string::npos);
}

TEST(Licence, TheCopyrightFileGivesEveryFileALicence) {
  const auto paragraphs = paragraphs_of(read_text(kSource / "packaging/copyright"));
  ASSERT_GE(paragraphs.size(), 3u);
  EXPECT_EQ(paragraphs[0].count("Format"), 1u) << "the header paragraph comes first";
  EXPECT_NE(paragraphs[0].at("Comment").find("Apache License 2.0"), std::string::npos);

  std::set<std::string> licences_with_text, licences_named;
  bool own_files_seen = false;
  const std::vector<std::string> files = source_files();
  for (std::size_t i = 1; i < paragraphs.size(); ++i) {
    const Paragraph& p = paragraphs[i];
    ASSERT_EQ(p.count("License"), 1u) << "paragraph " << i << " has no License field";
    const std::string& licence = p.at("License");
    const std::string name = first_line(licence);
    if (licence.find('\n') != std::string::npos) licences_with_text.insert(name);
    if (p.count("Files") == 0) continue;  // a stand-alone licence paragraph
    EXPECT_EQ(p.count("Copyright"), 1u) << p.at("Files") << ": no Copyright field";
    licences_named.insert(name);
    for (const std::string& pattern : words_of(p.at("Files"))) {
      if (pattern == "*") {
        own_files_seen = true;
        EXPECT_EQ(name, "Apache-2.0") << "Impasto's own files";
        continue;
      }
      bool matched = false;
      for (const std::string& file : files)
        matched = matched || fnmatch(pattern.c_str(), file.c_str(), 0) == 0;
      EXPECT_TRUE(matched) << "packaging/copyright names " << pattern << ", which matches no file";
    }
  }
  EXPECT_TRUE(own_files_seen) << "no 'Files: *' paragraph";
  for (const std::string& name : licences_named)
    EXPECT_EQ(licences_with_text.count(name), 1u) << "licence " << name << " has no text";
}

TEST(Licence, TheNoticeCreditsEveryThirdPartyFile) {
  const std::string notice = read_text(kSource / "NOTICE");
  EXPECT_NE(notice.find("Apache License, Version 2.0"), std::string::npos);
  for (const Paragraph& p : paragraphs_of(read_text(kSource / "packaging/copyright"))) {
    if (p.count("Files") == 0 || first_line(p.at("License")) == "Apache-2.0") continue;
    for (const std::string& pattern : words_of(p.at("Files"))) {
      // A pattern's folder (or the file itself) is where NOTICE names it.
      const std::string place = pattern.substr(0, pattern.find('*'));
      EXPECT_NE(notice.find(place), std::string::npos) << "NOTICE does not credit " << pattern;
    }
  }
}

}  // namespace
