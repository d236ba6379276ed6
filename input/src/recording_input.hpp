#pragma once
// A recording (stroke file, HID capture) opened for reading through files::InputFile: folders,
// devices and files over files::kMaxRecordingBytes are refused by name before anything is
// read; its errors come as InputFormatError, as the readers' own do.
#include <impasto/files/input_file.hpp>
#include <impasto/input/stroke_error.hpp>

#include <filesystem>
#include <memory>
#include <string>

namespace impasto::input::detail {

inline std::unique_ptr<files::InputFile> open_recording(const std::filesystem::path& path,
                                                        const std::string& what) {
  try {
    return std::make_unique<files::InputFile>(path, what, files::kMaxRecordingBytes);
  } catch (const std::runtime_error& e) {
    std::string problem = e.what();  // "<path>: <problem>": the path is the error's source
    const std::string prefix = path.string() + ": ";
    if (problem.rfind(prefix, 0) == 0) problem.erase(0, prefix.size());
    throw InputFormatError(path.string(), 0, "", problem);
  }
}

}  // namespace impasto::input::detail
