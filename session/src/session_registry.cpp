#include "impasto/session/session_registry.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <impasto/input/stroke_file.hpp>
#include <impasto/util/text.hpp>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace impasto::session {
namespace {

constexpr const char* kMagic = "impasto-session 1";

std::string entry_text(const SessionEntry& e) {
  std::ostringstream text;
  text << kMagic << "\n";
  text << "pid " << e.pid << "\n";
  text << "painting "
       << (e.painting ? util::line_encoded(e.painting->string()) : std::string("new")) << "\n";
  text << "strokes " << util::line_encoded(e.strokes.string()) << "\n";
  text << "autosave " << util::line_encoded(e.autosave.string()) << "\n";
  return text.str();
}

SessionEntry parse_entry(const std::filesystem::path& file, const std::string& text) {
  SessionEntry e;
  e.entry = file;
  e.id = file.stem().string();
  std::istringstream in(text);
  std::string line;
  if (!std::getline(in, line) || line != kMagic) {
    throw std::runtime_error(file.string() + ": not a session entry");
  }
  while (std::getline(in, line)) {
    const auto space = line.find(' ');
    if (space == std::string::npos) continue;
    const std::string key = line.substr(0, space);
    const std::string value = line.substr(space + 1);
    if (key == "pid") e.pid = std::atol(value.c_str());
    if (key == "painting" && value != "new") e.painting = util::line_decoded(value);
    if (key == "strokes") e.strokes = util::line_decoded(value);
    if (key == "autosave") e.autosave = util::line_decoded(value);
  }
  if (e.strokes.empty()) throw std::runtime_error(file.string() + ": names no recording");
  // The autosave lives beside the entry, whatever the entry says.
  e.autosave = file.parent_path() / (e.id + ".autosave.impasto");
  return e;
}

}  // namespace

LiveSession::LiveSession(const std::filesystem::path& folder, const std::string& id,
                         const std::optional<std::filesystem::path>& painting,
                         const std::filesystem::path& strokes) {
  entry_.id = id;
  entry_.entry = folder / (id + ".session");
  entry_.painting = painting;
  entry_.strokes = strokes;
  entry_.autosave = folder / (id + ".autosave.impasto");
  entry_.pid = static_cast<long>(::getpid());
  const auto fail = [&](const std::string& what) {
    const std::string why = std::strerror(errno);
    if (fd_ >= 0) ::close(fd_);
    throw std::runtime_error(entry_.entry.string() + ": " + what + ": " + why);
  };
  fd_ = ::open(entry_.entry.c_str(), O_RDWR | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0600);
  if (fd_ < 0) fail("cannot create the session entry");
  if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) fail("cannot lock the session entry");
  const std::string text = entry_text(entry_);
  if (::write(fd_, text.data(), text.size()) != static_cast<ssize_t>(text.size())) {
    ::unlink(entry_.entry.c_str());
    fail("cannot write the session entry");
  }
  ::fsync(fd_);
  if (const int dir = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC); dir >= 0) {
    ::fsync(dir);
    ::close(dir);
  }
}

void LiveSession::painting_saved_as(const std::filesystem::path& painting) {
  if (fd_ < 0 || entry_.painting == painting) return;
  entry_.painting = painting;
  const std::string text = entry_text(entry_);  // a few hundred bytes: one write
  if (::pwrite(fd_, text.data(), text.size(), 0) != static_cast<ssize_t>(text.size()) ||
      ::ftruncate(fd_, static_cast<off_t>(text.size())) != 0 || ::fsync(fd_) != 0) {
    throw std::runtime_error(entry_.entry.string() +
                             ": cannot update the session entry: " + std::strerror(errno));
  }
}

LiveSession::~LiveSession() {
  if (fd_ >= 0) ::close(fd_);
}

void LiveSession::end_cleanly() {
  ::unlink(entry_.autosave.c_str());
  ::unlink(entry_.entry.c_str());
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
}

namespace {

// The entries in `folder` whose lock is held (`held`: running sessions) or free (unfinished
// ones), newest first.
std::vector<SessionEntry> entries(const std::filesystem::path& folder, bool held,
                                  std::vector<std::string>* problems) {
  std::vector<std::pair<std::filesystem::file_time_type, SessionEntry>> found;
  std::error_code error;
  for (const auto& item : std::filesystem::directory_iterator(folder, error)) {
    if (item.path().extension() != ".session") continue;
    // Only plain files: opening a FIFO planted under this name would wait for a writer forever.
    std::error_code type_error;
    if (item.symlink_status(type_error).type() != std::filesystem::file_type::regular) continue;
    const int fd = ::open(item.path().c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) continue;
    struct stat info {};
    if (::fstat(fd, &info) != 0 || !S_ISREG(info.st_mode)) {  // swapped in since the check
      ::close(fd);
      continue;
    }
    // A running session holds its entry's lock; the lock of a dead one is gone with it.
    const bool live = ::flock(fd, LOCK_SH | LOCK_NB) != 0;
    std::string text;
    if (live == held) {
      char buffer[4096];
      ssize_t n = 0;
      while ((n = ::read(fd, buffer, sizeof buffer)) > 0 && text.size() < 65536) {
        text.append(buffer, static_cast<std::size_t>(n));
      }
    }
    ::close(fd);
    if (live != held) continue;
    try {
      SessionEntry entry = parse_entry(item.path(), text);
      std::error_code time_error;
      auto when = std::filesystem::last_write_time(entry.strokes, time_error);
      if (time_error) when = std::filesystem::last_write_time(item.path(), time_error);
      found.emplace_back(when, std::move(entry));
    } catch (const std::exception& e) {
      if (problems) problems->push_back(e.what());
    }
  }
  std::sort(found.begin(), found.end(),
            [](const auto& a, const auto& b) { return a.first > b.first; });
  std::vector<SessionEntry> sessions;
  for (auto& [when, entry] : found) sessions.push_back(std::move(entry));
  return sessions;
}

}  // namespace

std::vector<SessionEntry> unfinished_sessions(const std::filesystem::path& folder,
                                              std::vector<std::string>* problems) {
  return entries(folder, false, problems);
}

std::vector<SessionEntry> other_sessions_with(const std::filesystem::path& folder,
                                              const std::filesystem::path& painting) {
  std::vector<SessionEntry> others;
  std::error_code error;
  const auto wanted = std::filesystem::weakly_canonical(painting, error);
  for (SessionEntry& entry : entries(folder, true, nullptr)) {
    if (entry.pid == static_cast<long>(::getpid()) || !entry.painting) continue;
    std::error_code entry_error;
    if (std::filesystem::weakly_canonical(*entry.painting, entry_error) == wanted && !error &&
        !entry_error) {
      others.push_back(std::move(entry));
    }
  }
  return others;
}

bool has_work_to_recover(const SessionEntry& session) {
  std::error_code error;
  if (std::filesystem::exists(session.autosave, error)) return true;
  try {
    for (const auto& event : input::read_stroke_file(session.strokes).events) {
      const bool header = std::holds_alternative<input::CanvasEvent>(event) ||
                          std::holds_alternative<input::BrushEvent>(event) ||
                          std::holds_alternative<input::OriginEvent>(event) ||
                          std::holds_alternative<input::SavedEvent>(event);
      if (!header) return true;
    }
    return false;
  } catch (const std::exception&) {
    return true;
  }
}

void discard_session(const SessionEntry& session) {
  ::unlink(session.autosave.c_str());
  ::unlink(session.entry.c_str());
}

}  // namespace impasto::session
