#pragma once
// The conference layer's timing claims (seed 002 §V-B, §VI) as checks on every state an
// instance of the layer reaches (models/vn_layer/observers.hpp names the clauses).

#include "checker/checks.hpp"
#include "models/vn_layer/config.hpp"

namespace vn_layer {

// (T1)–(T4): violated with a shortest trace and the clause it breaks, in words.
checker::PropertyResult check_round_timing(const VnConfig& config, const tioa::Automaton& system,
                                           const checker::ExploreOptions& options);
// (Y), 002:232: violated with a shortest trace to two VNs that disagree.
checker::PropertyResult check_y_consistency(const VnConfig& config, const tioa::Automaton& system,
                                            const checker::ExploreOptions& options);
// (R): violated with a shortest trace to an active CN that will never send again.
checker::PropertyResult check_cn_reports(const VnConfig& config, const tioa::Automaton& system,
                                         const checker::ExploreOptions& options);
// Adds to `r` whether δ meets the paper's round-length rule (002:162) and the lattice's
// (docs/design/vn-layer.md C29).
void note_round_rules(const VnConfig& config, checker::PropertyResult& r);

} // namespace vn_layer
