#include "fem/assembly/interface_enforcement.hpp"

namespace bipot {

PairStatus reported_status(const PairResult& result) {
  if (result.beta > 0) return PairStatus::Bonded;
  switch (result.status) {
  case ContactStatus::Open:
    return PairStatus::Open;
  case ContactStatus::Stick:
    return PairStatus::Stick;
  case ContactStatus::Slip:
    return PairStatus::Slip;
  }
  return PairStatus::Open;
}

const char* to_string(PairStatus status) {
  switch (status) {
  case PairStatus::Open:
    return "open";
  case PairStatus::Stick:
    return "stick";
  case PairStatus::Slip:
    return "slip";
  case PairStatus::Bonded:
    return "bonded";
  }
  return "?";
}

} // namespace bipot
