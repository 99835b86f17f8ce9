#include "cli/time_note.hpp"

namespace cli {

std::string time_note(const std::string& quantum) {
  return "Time is discretised: one quantum = " + quantum +
         ". Over integer time a \"holds\" covers the behaviours of the dense-time model when "
         "every clock constraint is closed (<=, >=); strict constraints (<, >) are not covered "
         "(Henzinger, Manna, Pnueli, \"What good are digital clocks?\", ICALP 1992). A worst "
         "time in quanta is exact for the discretised model and a lower bound for dense time.";
}

} // namespace cli
