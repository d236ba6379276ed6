#include "window/document.hpp"

#include <impasto/util/text.hpp>

#include <impasto/input/stroke_import.hpp>
#include <impasto/render/render_painting.hpp>

#include <algorithm>
#include <cstdio>
#include <ctime>
#include <iostream>
#include <limits>
#include <stdexcept>
#include <utility>

#include "impasto/files/message_text.hpp"
#include "impasto/session/canvas_edit.hpp"
#include "impasto/session/disk_stamp.hpp"
#include "impasto/session/recent_files.hpp"
#include "impasto/session/recovery_folder.hpp"

namespace impasto::app::window {
namespace {

// An autosave waits for this long without pen input (or for options.autosave_seconds of
// painting), and never comes sooner than this after the last one.
constexpr double kAutosaveQuiet_s = 3.0;

// "Could not save /a/b.impasto: why", naming the file once (most errors name it already).
std::string failure_text(const std::string& failed, const std::filesystem::path& file,
                         const std::string& why) {
  if (why.find(file.string()) != std::string::npos) return failed + ": " + why;
  return failed + " " + file.string() + ": " + why;
}

// The painting a recovered session ends with, from its recording (rebuild.hpp).
session::RebuiltSession rebuild_entry(const session::SessionEntry& entry) {
  return rebuild_session(input::read_stroke_file(entry.strokes), session::ReplayOptions{});
}

// "NAME (RECORDING)", or "an untitled painting (RECORDING)", escaped for the screen.
std::string session_label(const std::optional<std::filesystem::path>& painting,
                          const std::filesystem::path& recording) {
  return (painting ? files::terminal_text(painting->filename().string())
                   : std::string("an untitled painting")) +
         " (" + files::terminal_text(recording.filename().string()) + ")";
}

}  // namespace

Document::Document(const PaintOptions& options, WindowState& state, PaletteBoardPanel& board)
    : options_(options), state_(state), board_(board) {
  std::optional<input::StrokeFile> strokes;
  if (options_.replay) strokes = input::load_strokes_any(*options_.replay);
  paintcore::Painting painting = [&] {
    if (options_.painting) return paintcore::Painting::load(*options_.painting);
    if (strokes) return paintcore::Painting(replay_canvas(*strokes, session::ReplayOptions{}));
    return paintcore::Painting(options_.new_canvas);
  }();
  open_board_for(options_.painting);
  worker_ = std::make_unique<session::SimWorker>(
      std::move(painting), begin_session(options_.painting, options_.painting));
  if (options_.painting) opened_file(*options_.painting);
  if (!options_.replay) find_recoverable_sessions();
  if (strokes) queue_replay(std::move(*strokes));
}

Document::~Document() = default;

// Sessions that did not end cleanly are offered for recovery.
void Document::find_recoverable_sessions() {
  try {
    for (auto& entry : session::unfinished_sessions(session::recovery_folder())) {
      // A session killed before anything was painted has nothing to offer.
      if (session::has_work_to_recover(entry)) {
        // Its recording stays whether it is recovered, left for later or discarded.
        earlier_sessions_.push_back(
            {"not ended cleanly: " + session_label(entry.painting, entry.strokes), entry.strokes});
        recoverable_.push_back(std::move(entry));
      } else {
        session::discard_session(entry);
      }
    }
  } catch (const std::exception&) {
    // no recovery folder: begin_session has said so
  }
}

std::vector<TimelapseSource> Document::timelapse_sources() const {
  std::vector<TimelapseSource> sources;
  if (const auto recording = worker_->recording_path())
    sources.push_back({"this session", *recording});
  sources.insert(sources.end(), earlier_sessions_.rbegin(), earlier_sessions_.rend());
  return sources;
}

// The recorded events take the same path as live input: the worker's queue.
void Document::queue_replay(input::StrokeFile strokes) {
  const bool has_load = std::any_of(
      strokes.events.begin(), strokes.events.end(),
      [](const input::StrokeEvent& e) { return std::holds_alternative<input::LoadEvent>(e); });
  worker_->set_auto_load(!has_load);
  for (const auto& warning : strokes.warnings) {
    std::cerr << "impasto: warning: " << warning << "\n";
    notice_ += (notice_.empty() ? "" : " ") + warning;
  }
  for (auto& event : strokes.events) {
    // The canvas is made above; where the replayed session began and was saved belongs to
    // that session, not to this one's recording.
    const bool header = std::holds_alternative<input::CanvasEvent>(event) ||
                        std::holds_alternative<input::OriginEvent>(event) ||
                        std::holds_alternative<input::SavedEvent>(event);
    if (!header) worker_->submit(std::move(event));
  }
  worker_->finish_stroke();
  worker_->set_auto_load(false);
}

session::SessionRecording Document::begin_session(
    const std::optional<std::filesystem::path>& painting,
    const std::optional<std::filesystem::path>& origin) {
  session::SessionRecording recording;
  recording.opened_from = origin;
  if (worker_) {  // the session ending: its recording can still be played as a time-lapse
    if (const auto recorded = worker_->recording_path())
      earlier_sessions_.push_back(
          {"earlier in this window: " + session_label(state_.file, *recorded), *recorded});
  }
  live_session_.reset();
  notice_.clear();
  if (options_.no_record) return recording;
  session::SessionStart start = session::start_session_recording(painting, options_.record);
  recording.recorder = std::move(start.recorder);
  recording.not_recording = start.not_recording;
  live_session_ = std::move(start.live);
  notice_ = start.notice;
  return recording;
}

void Document::end_session() {
  if (live_session_) live_session_->end_cleanly();
  live_session_.reset();
}

void Document::maybe_autosave(double now_s, bool in_stroke) {
  if (!live_session_ || in_stroke || !worker_->idle()) return;
  if (worker_->stats().events_since_autosave == 0) return;
  if (now_s - last_autosave_s_ < kAutosaveQuiet_s) return;
  const bool quiet = now_s - last_input_s_ >= kAutosaveQuiet_s;
  const bool due = now_s - last_autosave_s_ >= options_.autosave_seconds;
  if (!quiet && !due) return;
  worker_->autosave(live_session_->entry().autosave);
  last_autosave_s_ = now_s;
}

// The window now shows `file` as it is on disk: its name, its stamp (Save asks before
// replacing what another window saves over it later), the recent list; and a word when
// another window has it open too.
void Document::opened_file(const std::filesystem::path& file) {
  state_.file = file;
  state_.file_stamp = session::stamp_of(file);
  session::remember_recent_file(file);
  state_.recent = session::load_recent_files();
  try {
    for (const session::SessionEntry& other :
         session::other_sessions_with(session::recovery_folder(), file)) {
      state_.notifications.warning(files::terminal_text(file.filename().string()) +
                                   " is open in another Impasto window too (process " +
                                   std::to_string(other.pid) +
                                   "): Save asks before replacing what either saves.");
      break;
    }
  } catch (const std::exception&) {
    // no recovery folder: no other window can be known
  }
}

// The palette board kept beside the painting, or a clean one.
void Document::open_board_for(const std::optional<std::filesystem::path>& painting) {
  try {
    if (painting && std::filesystem::exists(PaletteBoard::file_beside(*painting))) {
      board_.replace(PaletteBoard::load(PaletteBoard::file_beside(*painting)));
      return;
    }
  } catch (const std::exception& e) {
    state_.notifications.warning("the palette board beside the painting was not read: " +
                                 std::string(e.what()));
  }
  board_.replace(PaletteBoard());
}

Document::Recovered Document::recover(const RecoveryChoice& choice) {
  if (choice.kind == RecoveryChoice::kNone) return Recovered::kNothing;
  if (choice.kind == RecoveryChoice::kLater) {
    recoverable_.clear();
    previewing_.reset();
    preview_.reset();
    return Recovered::kNothing;
  }
  const session::SessionEntry entry = recoverable_.at(choice.index);
  try {
    switch (choice.kind) {
      case RecoveryChoice::kPreview:
        preview_ = std::make_unique<session::RebuiltSession>(rebuild_entry(entry));
        previewing_ = choice.index;
        return Recovered::kPreviewReady;
      case RecoveryChoice::kRecover: {
        if (worker_->stats().events_since_save > 0) {
          state_.notifications.warning(
              "save or close this painting first (File menu), then recover");
          return Recovered::kNothing;
        }
        if (previewing_ != choice.index || !preview_) {
          preview_ = std::make_unique<session::RebuiltSession>(rebuild_entry(entry));
        }
        end_session();
        session::SessionRecording recording = begin_session(entry.painting, std::nullopt);
        // The new session starts from the recovered painting, kept as its first autosave and
        // read back from it, so that its `from` record names exactly what the file holds.
        paintcore::Painting recovered = std::move(preview_->painting);
        if (live_session_) {
          recovered.save(live_session_->entry().autosave);
          recovered = paintcore::Painting::load(live_session_->entry().autosave);
          recording.opened_from = live_session_->entry().autosave;
        }
        worker_->replace_painting(std::move(recovered), std::move(recording), true);
        open_board_for(entry.painting);
        if (entry.painting) {
          // Save goes back to the file, as it stands now (the session's last save).
          state_.file = entry.painting;
          state_.file_stamp = session::stamp_of(*entry.painting);
        }
        notice_ = "Recovered " +
                  (entry.painting ? entry.painting->filename().string()
                                  : std::string("an untitled painting")) +
                  " from its autosave and recording: save it to keep it.";
        state_.hidden_dry_layers.clear();
        break;
      }
      case RecoveryChoice::kDiscard:
        break;
      default:
        return Recovered::kNothing;
    }
  } catch (const std::exception& e) {
    state_.notifications.error(std::string("cannot recover: ") + e.what());
    return Recovered::kNothing;
  }
  const bool replaced = choice.kind == RecoveryChoice::kRecover;
  discard_session(entry);
  recoverable_.erase(recoverable_.begin() + static_cast<std::ptrdiff_t>(choice.index));
  previewing_.reset();
  preview_.reset();
  return replaced ? Recovered::kReplaced : Recovered::kNothing;
}

FileActions Document::file_actions() {
  FileActions actions;
  actions.save_over = [this](const std::filesystem::path& file) {
    try {
      worker_->save(file);
      state_.file = file;
      state_.file_stamp = session::stamp_of(file);
      notice_.clear();  // what the session's start or a recovery said is done with
      if (live_session_) live_session_->painting_saved_as(file);  // a recovery reopens it
      session::remember_recent_file(file);
      state_.recent = session::load_recent_files();
    } catch (const std::exception& e) {
      state_.notifications.error(failure_text("Could not save", file, e.what()));
      return false;
    }
    // The painting is saved; the board beside it is a convenience.
    try {
      board_.board().save(PaletteBoard::file_beside(file));
    } catch (const std::exception& e) {
      state_.notifications.warning("Saved the painting, but not its palette board: " +
                                   std::string(e.what()));
    }
    state_.notifications.info("Saved " + file.string());
    return true;
  };
  actions.save = [this, save_over = actions.save_over](const std::filesystem::path& file) {
    // Over the file this window read or wrote, changed since: ask before replacing that work.
    if (state_.file && file == *state_.file && changed_on_disk(file, state_.file_stamp)) {
      state_.ask_changed_on_disk = true;
      return false;
    }
    return save_over(file);
  };
  actions.export_image = [this](const std::filesystem::path& file) {
    try {
      worker_->wait_idle();
      worker_->with_painting([&](const paintcore::Painting& painting) {
        render::render_painting_to_file(painting, state_.settings, file);
      });
      state_.notifications.info("Exported " + file.string());
    } catch (const std::exception& e) {
      state_.notifications.error(failure_text("Could not export", file, e.what()));
    }
  };
  return actions;
}

bool Document::run_pending_action() {
  if (state_.pending == PendingAction::kNone || !state_.pending_confirmed) return false;
  const PendingAction action = state_.pending;
  state_.pending = PendingAction::kNone;
  state_.pending_confirmed = false;
  try {
    switch (action) {
      case PendingAction::kQuit:
        state_.quit = true;
        return false;
      case PendingAction::kNew: {
        paintcore::CanvasSpec spec = options_.new_canvas;
        spec.width_cells = state_.new_width;
        spec.height_cells = state_.new_height;
        spec.dpi = state_.new_dpi;
        paintcore::validate(spec);
        end_session();
        worker_->replace_painting(paintcore::Painting(spec),
                                  begin_session(std::nullopt, std::nullopt));
        open_board_for(std::nullopt);
        state_.file.reset();
        state_.notifications.info("New painting");
        break;
      }
      case PendingAction::kOpen:
      case PendingAction::kOpenRecent: {
        const auto file = state_.pending_path;
        paintcore::Painting opened = paintcore::Painting::load(file);
        end_session();
        worker_->replace_painting(std::move(opened), begin_session(file, file));
        open_board_for(file);
        opened_file(file);
        state_.notifications.info("Opened " + file.string());
        worker_->with_painting([&](const paintcore::Painting& p) {
          if (!p.load_warning().empty()) state_.notifications.warning(p.load_warning());
        });
        break;
      }
      case PendingAction::kNone:
        return false;
    }
  } catch (const std::exception& e) {
    // The painting shown is unchanged: nothing was replaced.
    state_.notifications.error(action == PendingAction::kNew
                                   ? std::string("Could not make the new painting: ") + e.what()
                                   : failure_text("Could not open", state_.pending_path, e.what()));
    return false;
  }
  state_.hidden_dry_layers.clear();
  return true;
}

// The Image menu. A crop or resize changes the canvas outside the session's events: the
// session starts again from the reframed painting, as opening a file does (kept as its first
// autosave and read back, so the recording's `from` names exactly what that file holds); the
// file carries the whole undo history, so Edit > Undo undoes the reframe.
bool Document::apply_canvas_request(const CanvasMenuRequest& request) {
  try {
    if (request.exports) {
      worker_->wait_idle();
      session::ExportRequest exports = *request.exports;
      exports.settings = state_.settings;  // the window's light and look
      session::ExportReport report;
      worker_->with_painting(
          [&](const paintcore::Painting& p) { report = export_painting(p, exports); });
      std::string said = "Exported at " + std::to_string(request.exports->scale) + "x";
      if (!exports.solids.empty())
        said += "; the solid: " + std::to_string(report.solid_triangles) + " triangles, " +
                util::number_text(report.solid_error_mm, 3) + " mm error";
      state_.notifications.info(said);
    }
    if (const auto& v = request.varnish) {
      // A session event like a stroke: recorded (a `varnish` record), replayed, undone.
      worker_->submit(input::StrokeEvent{*v});
      char text[96];
      std::snprintf(text, sizeof text, "Varnished %s, %.3g mm (wet until dried)",
                    std::string(paintcore::finish_name(v->finish)).c_str(), v->thickness_mm);
      state_.notifications.info(text);
    }
    if (!request.frame) return false;
    worker_->wait_idle();
    paintcore::PaintTotals cut;
    // (The stroke format has no record of a reframe: the session starts again from the
    // changed painting, its undo history whole.)
    worker_->edit_painting([&](paintcore::Painting& p) {
      cut = p.reframe_canvas(*request.frame);
      p.set_saved_history_bytes(std::numeric_limits<std::size_t>::max());
    });
    end_session();
    session::SessionRecording recording = begin_session(state_.file, std::nullopt);
    const std::filesystem::path through =
        live_session_ ? live_session_->entry().autosave
                      : std::filesystem::temp_directory_path() /
                            ("impasto-reframe-" + std::to_string(std::time(nullptr)) + ".impasto");
    worker_->with_painting([&](const paintcore::Painting& p) { p.save(through); });
    paintcore::Painting reframed = paintcore::Painting::load(through);
    if (live_session_)
      recording.opened_from = through;
    else
      std::filesystem::remove(through);
    worker_->replace_painting(std::move(reframed), std::move(recording), true);
    char text[96];
    std::snprintf(text, sizeof text, "Canvas %d x %d cells; %.3g mm^3 of paint cut away",
                  request.frame->width_cells, request.frame->height_cells, cut.volume);
    state_.notifications.info(text);
  } catch (const std::exception& e) {
    state_.notifications.error(std::string("Image: ") + e.what());
  }
  return true;  // a new size, or a failed reframe: new textures, fit it to the window
}

void Document::note_recording_failure() {
  if (recording_failure_.empty()) recording_failure_ = worker_->stats().recording_error;
}

void Document::close(bool terminated) {
  worker_->wait_idle();
  const bool unsaved = worker_->stats().events_since_save > 0;
  // Told to go with unsaved work: autosave it, and leave the session recoverable.
  if (terminated && unsaved && live_session_) {
    worker_->finish_stroke();
    worker_->autosave(live_session_->entry().autosave);
    worker_->wait_idle();
  }
  note_recording_failure();
  worker_.reset();  // syncs and closes the recording
  // Closed as the user chose: nothing to recover. A crash never gets here.
  if (!(terminated && unsaved)) end_session();
  // A session that could not be recorded fails the command, so scripts notice.
  if (!recording_failure_.empty()) throw std::runtime_error(recording_failure_);
}

PaintingSnapshot Document::snapshot() {
  return worker_->with_painting([](const paintcore::Painting& p) {
    PaintingSnapshot s;
    s.width_cells = p.canvas().width_cells();
    s.height_cells = p.canvas().height_cells();
    s.dpi = p.canvas().spec().dpi;
    s.undo_depth = p.undo_depth();
    s.redo_depth = p.redo_depth();
    s.dry_layers = p.canvas().dry_layers().size();
    s.slots = p.pigment_slots();
    s.brush_volume_mm3 = p.brush_totals().volume;
    s.brush_head = p.brush().head();
    s.brush_cells = p.brush().cells_across();
    return s;
  });
}

}  // namespace impasto::app::window
