// The window's notifications without a window: errors and warnings stay until dismissed,
// information fades, repeats are counted, and the stack stays small.
#include "window/notifications.hpp"

#include <gtest/gtest.h>

namespace impasto::app::window {
namespace {

TEST(Notifications, ErrorsStayUntilDismissedAndInformationFades) {
  Notifications notes;
  notes.post(NoteLevel::kError, "cannot save /x/y.impasto: no such folder", 0.0);
  notes.post(NoteLevel::kInfo, "saved", 0.0);
  notes.post(NoteLevel::kWarning, "low disk", 0.0);
  ASSERT_EQ(notes.notes().size(), 3u);
  notes.expire(Notifications::kInfoSeconds * 0.5);
  EXPECT_EQ(notes.notes().size(), 3u);
  notes.expire(Notifications::kInfoSeconds * 100.0);
  ASSERT_EQ(notes.notes().size(), 2u);
  EXPECT_EQ(notes.notes()[0].level, NoteLevel::kError);
  EXPECT_EQ(notes.notes()[1].level, NoteLevel::kWarning);
  notes.dismiss(notes.notes()[0].id);
  ASSERT_EQ(notes.notes().size(), 1u);
  EXPECT_EQ(notes.notes()[0].text, "low disk");
}

TEST(Notifications, TheSameTextAgainIsCountedNotStacked) {
  Notifications notes;
  notes.post(NoteLevel::kError, "disk full", 0.0);
  notes.post(NoteLevel::kError, "disk full", 1.0);
  notes.post(NoteLevel::kWarning, "disk full", 1.0);  // another level: another note
  ASSERT_EQ(notes.notes().size(), 2u);
  EXPECT_EQ(notes.notes()[0].repeats, 2);
  notes.post(NoteLevel::kError, "", 2.0);  // nothing to say: nothing shown
  EXPECT_EQ(notes.notes().size(), 2u);
}

TEST(Notifications, AFullStackDropsInformationBeforeErrors) {
  Notifications notes;
  notes.post(NoteLevel::kError, "first error", 0.0);
  notes.post(NoteLevel::kInfo, "some info", 0.0);
  for (std::size_t i = 0; i < Notifications::kMaxNotes; ++i) {
    notes.post(NoteLevel::kError, "error " + std::to_string(i), 1.0);
  }
  ASSERT_EQ(notes.notes().size(), Notifications::kMaxNotes);
  for (const Note& note : notes.notes()) EXPECT_NE(note.level, NoteLevel::kInfo);
  // Then the oldest: the newest errors are the ones kept.
  EXPECT_EQ(notes.notes().back().text, "error " + std::to_string(Notifications::kMaxNotes - 1));
}

}  // namespace
}  // namespace impasto::app::window
