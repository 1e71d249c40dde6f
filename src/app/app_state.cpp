#include "app/app_state.h"

namespace vox::app {

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
    case Panel::kThickness:
      return "thickness";
    case Panel::kParts:
      return "parts";
    case Panel::kPrint:
      return "print";
    case Panel::kCasting:
      return "casting";
  }
  return "model";
}

}  // namespace vox::app
