// The painting hands what its canvas marked changed on to each of its subscribers.
#include <stdexcept>
#include <string>

#include "painting_impl.hpp"

namespace impasto::paintcore {

namespace {

void see_everything(ChangedCells& subscriber, const Canvas& canvas) {
  (void)subscriber.take();
  subscriber.add_all(canvas.tile_count(), [&](int index) { return canvas.tile_cells(index); });
}

}  // namespace

void Painting::Impl::take_subscribers(std::vector<ChangedCells> others) {
  subscribers = std::move(others);
  for (ChangedCells& subscriber : subscribers) see_everything(subscriber, canvas);
}

Painting::ChangeSubscriber Painting::subscribe_changes() {
  impl_->subscribers.emplace_back();
  see_everything(impl_->subscribers.back(), impl_->canvas);
  return {static_cast<int>(impl_->subscribers.size()) - 1};
}

std::vector<DirtyTile> Painting::take_changes(ChangeSubscriber subscriber) {
  std::vector<ChangedCells>& subscribers = impl_->subscribers;
  if (subscriber.id < 0 || subscriber.id >= static_cast<int>(subscribers.size()))
    throw std::invalid_argument("painting: change subscriber " + std::to_string(subscriber.id) +
                                " was not subscribed to this painting");
  const std::vector<DirtyTile> marked = impl_->canvas.take_changes();
  for (ChangedCells& each : subscribers) each.add(marked);
  std::vector<DirtyTile> changes = subscribers[static_cast<std::size_t>(subscriber.id)].take();
  // A reframed canvas has fewer tiles: what was gathered before it no longer names one (the
  // reframe marked every tile of the new canvas).
  std::erase_if(changes, [&](const DirtyTile& d) { return d.index >= impl_->canvas.tile_count(); });
  return changes;
}

}  // namespace impasto::paintcore
