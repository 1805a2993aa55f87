#include "fem/core/interface_point.hpp"

namespace bipot {

const char* to_string(ContactStatus status) {
  switch (status) {
  case ContactStatus::Open:
    return "open";
  case ContactStatus::Stick:
    return "stick";
  case ContactStatus::Slip:
    return "slip";
  }
  return "?";
}

} // namespace bipot
