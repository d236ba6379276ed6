#include "window_services.hpp"

#include <memory>

namespace impasto::app {
namespace {

std::unique_ptr<WindowServices>& provided() {
  static std::unique_ptr<WindowServices> services;
  return services;
}

}  // namespace

const WindowServices* window_services() {
  return provided().get();
}

void provide_window_services(WindowServices services) {
  provided() = std::make_unique<WindowServices>(std::move(services));
}

}  // namespace impasto::app
