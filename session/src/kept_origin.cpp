#include "impasto/session/kept_origin.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <vector>

namespace impasto::session {
namespace {

std::string reason(int error_number) {
  return std::strerror(error_number);
}

// Copies `from` to the new file `to` (never through a file or link already there).
std::string copy_new_file(const std::filesystem::path& from, const std::filesystem::path& to) {
  const int in = ::open(from.c_str(), O_RDONLY | O_CLOEXEC);
  if (in < 0) return "cannot read " + from.string() + ": " + reason(errno);
  const int out = ::open(to.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
  if (out < 0) {
    const int error_number = errno;
    ::close(in);
    return "cannot create " + to.string() + ": " + reason(error_number);
  }
  std::string failure;
  char buffer[1 << 16];
  for (;;) {
    const ssize_t got = ::read(in, buffer, sizeof buffer);
    if (got == 0) break;
    if (got < 0) {
      if (errno == EINTR) continue;
      failure = "cannot read " + from.string() + ": " + reason(errno);
      break;
    }
    for (ssize_t done = 0; done < got && failure.empty();) {
      const ssize_t put = ::write(out, buffer + done, static_cast<std::size_t>(got - done));
      if (put < 0 && errno == EINTR) continue;
      if (put < 0) failure = "cannot write " + to.string() + ": " + reason(errno);
      done += put;
    }
    if (!failure.empty()) break;
  }
  ::close(in);
  if (::close(out) != 0 && failure.empty()) failure = "cannot write " + to.string();
  if (!failure.empty()) ::unlink(to.c_str());
  return failure;
}

// Of a painting's sessions recorded in one folder ("NAME.session-STAMP.strokes", STAMP in
// time order), only the newest kKeptOrigins keep their origin: each kept one holds a version
// of the painting once it is saved over, so the folder would otherwise grow by a painting a
// session. An older session's time-lapse then starts on a blank canvas, with a warning.
void prune_kept_origins(const std::filesystem::path& recording) {
  const std::string name = recording.filename().string();
  const std::size_t session = name.rfind(".session-");
  if (session == std::string::npos) return;  // a recording named by hand: its own business
  const std::string prefix = name.substr(0, session + 9);
  std::vector<std::filesystem::path> kept;
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator(recording.parent_path(), error)) {
    const std::string other = entry.path().filename().string();
    if (other.starts_with(prefix) && other.ends_with(".origin") &&
        entry.symlink_status(error).type() == std::filesystem::file_type::regular)
      kept.push_back(entry.path());
  }
  if (kept.size() <= kKeptOrigins) return;
  std::sort(kept.begin(), kept.end());
  for (std::size_t i = 0; i + kKeptOrigins < kept.size(); ++i)
    std::filesystem::remove(kept[i], error);
}

}  // namespace

std::filesystem::path kept_origin_path(const std::filesystem::path& recording) {
  std::filesystem::path kept = recording;
  return kept.replace_extension(".origin");
}

std::string keep_origin(const std::filesystem::path& painting,
                        const std::filesystem::path& recording) {
  const std::filesystem::path kept = kept_origin_path(recording);
  // A link where the file system allows one (the painting's folder holds the recording).
  std::string failure;
  if (::linkat(AT_FDCWD, painting.c_str(), AT_FDCWD, kept.c_str(), AT_SYMLINK_FOLLOW) != 0) {
    failure = errno == EEXIST ? kept.string() + " is already there" : copy_new_file(painting, kept);
  }
  if (failure.empty()) prune_kept_origins(recording);
  return failure;
}

OriginCandidates origin_candidates(const input::StrokeFile& file) {
  OriginCandidates candidates;
  for (std::size_t i = 0; i < file.events.size(); ++i) {
    const auto* origin = std::get_if<input::OriginEvent>(&file.events[i]);
    if (origin == nullptr) continue;
    if (origin->new_canvas) return candidates;
    candidates.files.push_back(origin->painting);
    if (!file.source.empty()) candidates.files.push_back(kept_origin_path(file.source));
    candidates.state_hash = origin->state_hash;
    candidates.where = file.where(i);
    return candidates;
  }
  return candidates;
}

std::optional<paintcore::Painting> load_session_origin(const input::StrokeFile& file, int threads,
                                                       std::vector<std::string>& warnings) {
  const OriginCandidates candidates = origin_candidates(file);
  if (candidates.files.empty()) return std::nullopt;
  for (const auto& candidate : candidates.files) {
    try {
      paintcore::Painting painting = paintcore::Painting::load(candidate, threads);
      if (painting.state_hash() == candidates.state_hash) return painting;
    } catch (const std::exception&) {
      // gone, unreadable or not a painting: the next candidate may hold the state
    }
  }
  warnings.push_back(candidates.where + ": the painting the session began from (" +
                     candidates.files.front().string() +
                     ") is gone or has changed, and no copy of it is kept beside the recording: "
                     "the strokes are shown on a blank canvas, without that painting's own paint");
  return std::nullopt;
}

}  // namespace impasto::session
