#include "impasto/session/rebuild.hpp"

#include <chrono>
#include <optional>
#include <stdexcept>

#include "impasto/files/memory_budget.hpp"
#include "impasto/session/kept_origin.hpp"

namespace impasto::session {
namespace {

struct Mark {
  std::size_t next = 0;  // the first record to replay after it
  std::string painting;
  std::uint64_t state_hash = 0;
  std::string where;
};

std::vector<Mark> marks_of(const input::StrokeFile& file) {
  std::vector<Mark> marks;
  for (std::size_t i = 0; i < file.events.size(); ++i) {
    if (const auto* origin = std::get_if<input::OriginEvent>(&file.events[i])) {
      if (!origin->new_canvas) {
        // The copy kept beside the recording (kept_origin.hpp), tried after the file itself:
        // marks are tried from the last.
        if (!file.source.empty())
          marks.push_back(
              {i + 1, kept_origin_path(file.source).string(), origin->state_hash, file.where(i)});
        marks.push_back({i + 1, origin->painting, origin->state_hash, file.where(i)});
      }
    } else if (const auto* saved = std::get_if<input::SavedEvent>(&file.events[i])) {
      marks.push_back({i + 1, saved->painting, saved->state_hash, file.where(i)});
    }
  }
  return marks;
}

// The mark's painting, when its file still holds the state the mark names.
std::optional<paintcore::Painting> load_mark(const Mark& mark, const ReplayOptions& options) {
  try {
    paintcore::Painting painting = paintcore::Painting::load(mark.painting, options.threads);
    if (painting.state_hash() == mark.state_hash) return painting;
  } catch (const std::exception&) {
    // gone, unreadable, or changed since: an earlier mark may do
  }
  return std::nullopt;
}

// Replays records [first, end) onto `painting`. False when an undo would reach back past
// `first` (the base has no history to undo), so an earlier base must be used.
bool replay_from(paintcore::Painting& painting, const input::StrokeFile& file, std::size_t first,
                 const ReplayOptions& options, bool check_undo, ReplayReport& report) {
  SessionPlayer player(painting, options, options.auto_load && !has_load_record(file));
  const auto start = std::chrono::steady_clock::now();
  for (std::size_t i = first; i < file.events.size(); ++i) {
    const auto& event = file.events[i];
    if (check_undo && std::holds_alternative<input::UndoEvent>(event)) {
      player.finish();
      if (painting.undo_depth() == 0) return false;
    }
    try {
      player.apply(event);
    } catch (const std::exception& e) {
      throw std::runtime_error(file.where(i) + ": " + files::error_text(e));
    }
    if (options.progress) options.progress(i + 1, file.events.size());
  }
  player.finish();
  report = player.report();
  report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return true;
}

}  // namespace

RebuiltSession rebuild_session(const input::StrokeFile& file, const ReplayOptions& options) {
  std::vector<std::string> warnings = file.warnings;
  const std::vector<Mark> marks = marks_of(file);
  for (auto mark = marks.rbegin(); mark != marks.rend(); ++mark) {
    std::optional<paintcore::Painting> base = load_mark(*mark, options);
    if (!base) continue;
    ReplayReport report;
    if (!replay_from(*base, file, mark->next, options, true, report)) continue;
    return {std::move(*base),
            mark->painting + " as marked at " + mark->where + ", and the records after it",
            warnings, report};
  }
  for (const auto& event : file.events) {
    const auto* origin = std::get_if<input::OriginEvent>(&event);
    if (origin && !origin->new_canvas) {
      warnings.push_back(file.source + ": the painting the session began from (" +
                         origin->painting +
                         ") is gone or has changed, and no save it marks is left: rebuilt on a "
                         "blank canvas, without that painting's own paint");
    }
  }
  paintcore::Painting painting(replay_canvas(file, options), options.threads);
  painting.set_params(replay_params(options));
  ReplayReport report;
  replay_from(painting, file, 0, options, false, report);
  return {std::move(painting), "the whole recording, replayed onto a new canvas", warnings, report};
}

}  // namespace impasto::session
