#include "app/app_state.h"

#include <chrono>

namespace vox::app {

double nowSeconds() {
  using namespace std::chrono;
  return duration<double>(steady_clock::now().time_since_epoch()).count();
}

const char* panelName(Panel p) {
  switch (p) {
    case Panel::kModel:
      return "model";
    case Panel::kSection:
      return "section";
    case Panel::kSkin:
      return "skin";
    case Panel::kXray:
      return "xray";
    case Panel::kMass:
      return "mass";
  }
  return "model";
}

}  // namespace vox::app
