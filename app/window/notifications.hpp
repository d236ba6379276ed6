#pragma once
// What the window has to tell the painter, shown as a stack of notes in the lower-left
// corner over the canvas, their text wrapped: errors and warnings stay until dismissed
// (their x), information fades after a few seconds. Anything that used to write to the
// status bar reports here instead (WindowState::notifications).
#include <cstdint>
#include <string>
#include <vector>

namespace impasto::app::window {

enum class NoteLevel { kInfo, kWarning, kError };

struct Note {
  std::uint64_t id = 0;
  NoteLevel level = NoteLevel::kInfo;
  std::string text;
  double posted_s = 0.0;  // when last posted (now_s())
  int repeats = 1;        // the same text posted again while shown counts here
};

class Notifications {
 public:
  // How long information stays on screen.
  static constexpr double kInfoSeconds = 6.0;
  // At most this many notes are kept; the oldest information goes first, then the oldest.
  static constexpr std::size_t kMaxNotes = 6;

  // Seconds on the steady clock: the times the notes are posted and expired at.
  static double now_s();

  void post(NoteLevel level, std::string text, double at_s);
  void info(std::string text) { post(NoteLevel::kInfo, std::move(text), now_s()); }
  void warning(std::string text) { post(NoteLevel::kWarning, std::move(text), now_s()); }
  void error(std::string text) { post(NoteLevel::kError, std::move(text), now_s()); }

  void dismiss(std::uint64_t id);
  // Drops information older than kInfoSeconds.
  void expire(double at_s);
  const std::vector<Note>& notes() const { return notes_; }

  // Draws the notes (ImGui, inside a frame), with a button to dismiss each; expires first.
  void draw();

 private:
  std::vector<Note> notes_;
  std::uint64_t next_id_ = 1;
};

}  // namespace impasto::app::window
