// docs/architecture.md against the tree: its module table names each module's dependencies as
// the build declares them, and only the window (and the GL renderer, for GL) includes the
// window system's, ImGui's and OpenGL's headers.
#include <gtest/gtest.h>

#include <array>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
const fs::path kSource = IMPASTO_SOURCE_DIR;

std::string read(const fs::path& file) {
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

using Modules = std::map<std::string, std::set<std::string>>;  // module -> impasto modules

// Each `impasto_module(NAME DEPS ... PRIVATE_DEPS ...)` call under the libraries' folders.
// The libraries' folders (app/ links them; it is read for the include rule only).
constexpr std::array kLibraryFolders = {"util",   "files",  "paintcore", "input", "data",
                                        "optics", "render", "session",   "bench"};

Modules modules_in_the_build() {
  Modules modules;
  const std::regex call(R"(impasto_module\(\s*(\w+)([^)]*)\))");
  const std::regex dependency(R"(impasto::(\w+))");
  for (const char* top : kLibraryFolders)
    for (const auto& entry : fs::recursive_directory_iterator(kSource / top)) {
      if (entry.path().filename() != "CMakeLists.txt") continue;
      const std::string text = read(entry.path());
      for (std::sregex_iterator m(text.begin(), text.end(), call), end; m != end; ++m) {
        std::set<std::string>& deps = modules[(*m)[1]];
        const std::string args = (*m)[2];
        for (std::sregex_iterator d(args.begin(), args.end(), dependency); d != end; ++d)
          deps.insert((*d)[1]);
      }
    }
  return modules;
}

// The table's rows `| `impasto::NAME` | folder | deps | face |`: the names in backticks
// before the column's first semicolon (the third-party libraries follow it).
Modules modules_in_the_table() {
  Modules modules;
  std::istringstream doc(read(kSource / "docs" / "architecture.md"));
  const std::regex row(R"(^\| `impasto::(\w+)` \| [^|]* \| ([^|]*) \|)");
  const std::regex name("`(\\w+)`");
  for (std::string line; std::getline(doc, line);) {
    std::smatch m;
    if (!std::regex_search(line, m, row)) continue;
    const std::string column = m[2].str().substr(0, m[2].str().find(';'));
    std::set<std::string>& deps = modules[m[1]];
    for (std::sregex_iterator d(column.begin(), column.end(), name), end; d != end; ++d)
      deps.insert((*d)[1]);
  }
  return modules;
}

TEST(Architecture, TheModuleTableNamesEachModulesDependencies) {
  const Modules built = modules_in_the_build(), documented = modules_in_the_table();
  ASSERT_GE(built.size(), 11u);  // util, files, paintcore, input, data, render, ... bench
  for (const auto& [module, deps] : built) {
    const auto row = documented.find(module);
    ASSERT_NE(row, documented.end()) << "docs/architecture.md has no row for impasto::" << module;
    EXPECT_EQ(row->second, deps) << "impasto::" << module << "'s dependencies";
  }
  for (const auto& [module, deps] : documented)
    EXPECT_TRUE(built.contains(module)) << "the table's impasto::" << module << " is not built";
}

// Every #include of a header of the families named, in sources outside `allowed`.
std::vector<std::string> includes_outside(const std::regex& family,
                                          const std::vector<fs::path>& allowed) {
  std::vector<std::string> found;
  std::vector<std::string> tops(kLibraryFolders.begin(), kLibraryFolders.end());
  tops.push_back("app");
  for (const std::string& top : tops)
    for (const auto& entry : fs::recursive_directory_iterator(kSource / top)) {
      const fs::path& file = entry.path();
      if (file.extension() != ".cpp" && file.extension() != ".hpp") continue;
      bool inside = false;
      for (const fs::path& folder : allowed) {
        const std::string path = file.string(), prefix = (kSource / folder).string() + "/";
        inside = inside || path.rfind(prefix, 0) == 0;
      }
      if (inside) continue;
      std::istringstream text(read(file));
      int number = 0;
      for (std::string line; std::getline(text, line);) {
        ++number;
        if (std::regex_search(line, family))
          found.push_back(fs::relative(file, kSource).string() + ":" + std::to_string(number));
      }
    }
  return found;
}

TEST(Architecture, OnlyTheWindowIncludesGlGlfwOrImGui) {
  const std::regex window_system(R"(^\s*#\s*include\s*[<"](GLFW/|imgui|backends/imgui))");
  const std::regex gl(R"(^\s*#\s*include\s*[<"](GL/|GLES|EGL/|glad/))");
  EXPECT_EQ(includes_outside(window_system, {"app/window"}), std::vector<std::string>{});
  EXPECT_EQ(includes_outside(gl, {"app/window", "render/gl"}), std::vector<std::string>{});
  // And the rule can see an include: the window has them.
  EXPECT_FALSE(includes_outside(window_system, {}).empty());
}

}  // namespace
