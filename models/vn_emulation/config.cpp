#include "models/vn_emulation/config.hpp"

namespace vn_emulation {

std::optional<std::string> invalid(const EmuConfig& c) {
  if (c.zones < 1 || c.zones > 2)
    return "zones must be 1 or 2, not " + std::to_string(c.zones);
  if (c.rp2 < 1 || c.rp2 > 40)
    return "rp2 must be 1..40, not " + std::to_string(c.rp2);
  if (c.moves < 0 || c.moves > 4)
    return "moves must be 0..4, not " + std::to_string(c.moves);
  if (c.pns < 1 || c.pns > 3)
    return "pns must be 1..3, not " + std::to_string(c.pns);
  if (c.d_p < 1 || c.d_p > 3)
    return "d_p must be 1..3, not " + std::to_string(c.d_p);
  if (c.eps < 0 || c.eps > 3)
    return "eps must be 0..3, not " + std::to_string(c.eps);
  if (c.messages < 0 || c.messages > 3)
    return "messages must be 0..3, not " + std::to_string(c.messages);
  if (c.fails < 0 || c.fails > 3)
    return "fails must be 0..3, not " + std::to_string(c.fails);
  if (c.buffer < 2 || c.buffer > EmuConfig::max_buffer_capacity)
    return "buffer must be 2.." + std::to_string(EmuConfig::max_buffer_capacity) + ", not " +
           std::to_string(c.buffer);
  return std::nullopt;
}

std::string describe(const EmuConfig& c) {
  const std::string geometry = c.zones == 1 ? "one zone, "
                                            : "two zones, rp2=" + std::to_string(c.rp2) +
                                                  ", moves=" + std::to_string(c.moves) + ", ";
  return geometry + "pns=" + std::to_string(c.pns) + ", d_p=" + std::to_string(c.d_p) +
         ", eps=" + std::to_string(c.eps) + ", messages=" + std::to_string(c.messages) +
         ", fails=" + std::to_string(c.fails) +
         ", start=" + (c.start == Start::cold ? "cold" : "warm") +
         ", inputs=" + (c.inputs == Inputs::anywhere ? "anywhere" : "ticks") +
         (c.vn == Vn::report ? ", vn=report"
          : c.vn == Vn::mc   ? ", vn=mc"
                             : "") +
         (c.ties == Ties::content ? ", ties=content (a repair of E4)" : "") +
         (c.reset_joined ? ", reset=joined (a repair of E5)" : "") +
         (c.tobcast_zone_at_delivery ? ", tobcast_zone=delivery" : "") +
         (c.printed_init_action ? ", init_action=printed" : "") +
         (c.printed_restart ? ", restart=printed" : "") +
         (c.buffer != EmuConfig{}.buffer ? ", buffer=" + std::to_string(c.buffer) : "");
}

} // namespace vn_emulation
