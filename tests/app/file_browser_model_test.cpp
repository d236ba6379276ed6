// The file browser's decisions without a window: what each purpose lists, the name it
// proposes, typed paths, extensions, and the folders remembered across sessions.
#include "window/file_browser_model.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <string>

#include "window/window_title.hpp"

namespace impasto::app::window {
namespace {

namespace fs = std::filesystem;

fs::path fresh_folder(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / (name + "_" + std::to_string(getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

void touch(const fs::path& file) {
  std::ofstream(file) << "x";
}

TEST(FileBrowserModel, ExportProposesThePaintingsStemAsPngNeverItsPath) {
  const fs::path painting = "/nonexistent/dir/x.impasto";
  EXPECT_EQ(proposed_file_name(FilePurpose::kExportImage, painting), "x.png");
  EXPECT_EQ(proposed_file_name(FilePurpose::kExportImage, std::nullopt), "Untitled.png");
  EXPECT_EQ(proposed_file_name(FilePurpose::kSavePainting, painting), "x.impasto");
  EXPECT_EQ(proposed_file_name(FilePurpose::kSavePainting, std::nullopt), "Untitled.impasto");
  EXPECT_EQ(proposed_file_name(FilePurpose::kOpenPainting, painting), "");
}

TEST(FileBrowserModel, FiltersTakeTheirExtensionsWhateverTheCase) {
  const auto open = filters_for(FilePurpose::kOpenPainting);
  ASSERT_GE(open.size(), 2u);
  EXPECT_TRUE(filter_matches(open[0], "a/b.impasto"));
  EXPECT_TRUE(filter_matches(open[0], "B.IMPASTO"));
  EXPECT_FALSE(filter_matches(open[0], "b.png"));
  EXPECT_FALSE(filter_matches(open[0], "impasto"));
  // A painting's palette board is kept beside it, not opened as a painting.
  EXPECT_FALSE(filter_matches(open[0], "study.palette.impasto"));
  EXPECT_TRUE(filter_matches(open.back(), "anything.txt"));  // All files
  const auto image = filters_for(FilePurpose::kExportImage);
  ASSERT_EQ(image.size(), 2u);
  EXPECT_TRUE(filter_matches(image[0], "p.png"));
  EXPECT_TRUE(filter_matches(image[1], "p.exr"));
  EXPECT_FALSE(filter_matches(image[0], "p.exr"));
  // What writes offers no "All files": the type written must be one the program writes.
  for (const auto& f : filters_for(FilePurpose::kSavePainting)) EXPECT_FALSE(f.extensions.empty());
  for (const auto& f : image) EXPECT_FALSE(f.extensions.empty());
  EXPECT_TRUE(writes_file(FilePurpose::kExportImage));
  EXPECT_FALSE(writes_file(FilePurpose::kOpenPainting));
}

TEST(FileBrowserModel, TypedNamesGetTheFiltersExtension) {
  const FileFilter png{"PNG", {".png"}};
  EXPECT_EQ(with_filter_extension("picture", png), "picture.png");
  EXPECT_EQ(with_filter_extension("picture.PNG", png), "picture.PNG");
  EXPECT_EQ(with_filter_extension("x.impasto", png), "x.png");  // carried over: replaced
  EXPECT_EQ(with_filter_extension("study.exr", png), "study.png");
  EXPECT_EQ(with_filter_extension("v1.2", png), "v1.2.png");  // not a kind: appended
  EXPECT_EQ(with_filter_extension("", png), "");
  EXPECT_EQ(with_filter_extension("notes.txt", FileFilter{"All", {}}), "notes.txt");
}

TEST(FileBrowserModel, TypedPathsAreReadAgainstTheFolderShown) {
  setenv("HOME", "/home/painter", 1);
  EXPECT_EQ(resolve_typed_path("/a/b", "c.impasto"), fs::path("/a/b/c.impasto"));
  EXPECT_EQ(resolve_typed_path("/a/b", "../c"), fs::path("/a/c"));
  EXPECT_EQ(resolve_typed_path("/a/b", "/tmp/x/"), fs::path("/tmp/x"));
  EXPECT_EQ(resolve_typed_path("/a/b", "~"), fs::path("/home/painter"));
  EXPECT_EQ(resolve_typed_path("/a/b", "~/art/x.png"), fs::path("/home/painter/art/x.png"));
  EXPECT_EQ(resolve_typed_path("/a/b", "./d/./e"), fs::path("/a/b/d/e"));
}

TEST(FileBrowserModel, AFolderListsItsFoldersFirstThenTheFilesTheFilterTakes) {
  const fs::path dir = fresh_folder("impasto_browser_listing");
  fs::create_directories(dir / "zeta");
  fs::create_directories(dir / "Alpha");
  fs::create_directories(dir / ".hidden_folder");
  touch(dir / "b.impasto");
  touch(dir / "A.impasto");
  touch(dir / "c.png");
  touch(dir / ".secret.impasto");
  std::string error;
  const auto entries =
      list_folder(dir, filters_for(FilePurpose::kOpenPainting).front(), false, &error);
  EXPECT_TRUE(error.empty()) << error;
  std::vector<std::string> names;
  for (const auto& e : entries) names.push_back(e.name + (e.is_folder ? "/" : ""));
  EXPECT_EQ(names, (std::vector<std::string>{"Alpha/", "zeta/", "A.impasto", "b.impasto"}));
  const auto with_hidden =
      list_folder(dir, filters_for(FilePurpose::kOpenPainting).front(), true, &error);
  EXPECT_EQ(with_hidden.size(), 6u);
  list_folder(dir / "missing", FileFilter{"All", {}}, false, &error);
  EXPECT_NE(error.find("missing"), std::string::npos) << error;
  fs::remove_all(dir);
}

TEST(FileBrowserModel, TheLastFolderOfEachPurposeIsRememberedAcrossSessions) {
  const fs::path dir = fresh_folder("impasto_browser_memory");
  fs::create_directories(dir / "exports");
  fs::create_directories(dir / "paintings");
  const fs::path list = dir / "config" / "folders.txt";
  {
    FolderMemory memory(list);
    EXPECT_FALSE(memory.folder_for(FilePurpose::kExportImage));
    memory.remember(FilePurpose::kExportImage, dir / "exports");
    memory.remember(FilePurpose::kSavePainting, dir / "paintings");
  }
  const FolderMemory later(list);  // a new session reads the file
  EXPECT_EQ(later.folder_for(FilePurpose::kExportImage), dir / "exports");
  // Opening and saving paintings share their folder.
  EXPECT_EQ(later.folder_for(FilePurpose::kOpenPainting), dir / "paintings");
  EXPECT_EQ(later.folders().size(), 2u);
  // Export starts in the last export folder, not beside the painting.
  EXPECT_EQ(starting_folder(later, FilePurpose::kExportImage, dir / "paintings" / "x.impasto"),
            dir / "exports");
  // Save as starts beside the painting, whatever folder saving used last.
  fs::create_directories(dir / "elsewhere");
  EXPECT_EQ(starting_folder(later, FilePurpose::kSavePainting, dir / "elsewhere" / "y.impasto"),
            dir / "elsewhere");
  EXPECT_EQ(starting_folder(later, FilePurpose::kSavePainting, std::nullopt), dir / "paintings");
  // A folder since removed is forgotten: the painting's folder, else the folder Impasto was
  // started in.
  fs::remove_all(dir / "exports");
  const FolderMemory after_removal(list);
  EXPECT_FALSE(after_removal.folder_for(FilePurpose::kExportImage));
  EXPECT_EQ(starting_folder(after_removal, FilePurpose::kExportImage, dir / "x.impasto"), dir);
  EXPECT_EQ(starting_folder(after_removal, FilePurpose::kExportImage, std::nullopt),
            fs::current_path());
  fs::remove_all(dir);
}

TEST(WindowTitle, NamesTheFileAndMarksUnsavedWork) {
  EXPECT_EQ(window_title(std::nullopt, false), "Untitled \u2014 Impasto");
  EXPECT_EQ(window_title(fs::path("/a/study.impasto"), false), "study.impasto \u2014 Impasto");
  EXPECT_EQ(window_title(fs::path("/a/study.impasto"), true),
            "\u2022 study.impasto \u2014 Impasto");
}

}  // namespace
}  // namespace impasto::app::window
