#include "catalogue/vn_layer.hpp"

#include <memory>

#include "catalogue/fig7_figures.hpp"
#include "models/vn_layer/layer.hpp"
#include "proofs/vn_layer/layer_checks.hpp"
#include "proofs/vn_layer/round_closure.hpp"
#include "proofs/vn_layer/round_legal_set.hpp"
#include "proofs/vn_layer/round_refinement.hpp"
#include "proofs/vn_layer/stabilisation.hpp"
#include "tioa/operators.hpp"

namespace catalogue {

vn_layer::VnConfig vn_layer_config(const ParamValues& p) {
  vn_layer::VnConfig c;
  c.rows = whole(p, "rows");
  c.cols = whole(p, "cols");
  c.nbh = whole(p, "nbh") == 4 ? mc::Neighbourhood::four : mc::Neighbourhood::eight;
  c.cns = whole(p, "cns");
  c.b = whole(p, "b");
  c.delta = whole(p, "delta");
  c.d_v = whole(p, "d_v");
  c.d_mmt = whole(p, "d_mmt");
  c.eps = whole(p, "eps");
  c.d_r = whole(p, "d_r");
  c.vc = whole(p, "vc");
  c.k = whole(p, "k");
  c.rho1 = p.at("rho1").rational();
  c.rho2 = p.at("rho2").rational();
  c.cn_fail = p.at("cn_fail").text() == "keep" ? vn_layer::CnFail::keep : vn_layer::CnFail::reset;
  const std::string vn_fail = p.at("vn_fail").text();
  c.vn_fail = vn_fail == "never" ? vn_layer::VnFail::never
              : vn_fail == "any" ? vn_layer::VnFail::any
                                 : vn_layer::VnFail::empty;
  c.vns_start_failed = p.at("vn_start").text() == "failed";
  c.owned_ends = whole(p, "owned_ends") == 1;
  return c;
}

ModelDefinition vn_layer_definition() {
  ModelDefinition d;
  d.name = "vn-layer";
  d.description = "the conference virtual-node layer: CN(delta)_i and VN(e, rho1, rho2)_h of "
                  "seed 001 Figs. 2-3 / seed 002 Figs. 5-6 with VLBcast and the VN restarts, "
                  "on a rows x cols grid with a b x b lattice per zone (time: quanta; "
                  "models/vn_layer/README.md)";
  d.params = {
      {"rows", 2, 1, 4, "rows of zones"},
      {"cols", 1, 1, 4, "columns of zones (at most 4 zones)"},
      {"nbh", 4, 4, 8, "neighbourhood: 4 (seeds 001/002) or 8"},
      {"cns", 2, 1, 3, "number of client nodes"},
      {"b", 2, 2, 8, "lattice units per zone side (even)"},
      {"delta", 13, 2, 64, "round length delta in quanta (seed 002 §V-B)"},
      {"d_v", 1, 1, 16, "VLBcast delay bound d_v"},
      {"d_mmt", 1, 0, 16, "upper bound d_MMT of the VN's send task"},
      {"eps", 1, 0, 16, "the slack eps of the CN's trigger times"},
      {"d_r", 1, 0, 16, "VN start-up time d_r"},
      {"vc", 2, 1, 16, "CN speed v_c, lattice units per quantum in each coordinate"},
      {"k", 1, 1, 3, "safety parameter (the conference's e)"},
      {"rho1", ParamValue(mc::Rational(1, 2)), 0, 1, "damping of calctarget", ParamKind::rational,
       true, true},
      {"rho2", ParamValue(mc::Rational(9, 10)), 0, 1, "damping of assign", ParamKind::rational,
       true, true},
      ParamSpec::choice("start", "all", {"all", "corner"},
                        "all: the CNs at every placement on the lattice; corner: all at the "
                        "bottom-left corner"),
      {"cn_faults", 0, 0, 1, "1: CNs fail and recover at any time after the start"},
      ParamSpec::choice("cn_fail", "reset", {"reset", "keep"},
                        "a failing CN resets its internal variables (seed 002 line 35) or "
                        "keeps them (seed 001 line 36)"),
      ParamSpec::choice("vn_fail", "empty", {"empty", "never", "any"},
                        "when a VN may fail: only while no active CN is in its zone (the "
                        "emulation), never, or at any time (the layer's text)"),
      ParamSpec::choice("vn_start", "failed", {"failed", "alive"},
                        "the VNs at time 0 (unstated; the emulation has no VNE yet)"),
      ParamSpec::change("owned_ends",
                        "1: calctarget's lines 35-36 aim at the ends of Gamma_h that zone h "
                        "owns (vlayer-mc README D14)")};
  d.properties = {
      {"no-timelock", "every reachable state has an action or a tick"},
      {"round-timing", "(T1)-(T4): cn-updates before the exchange-trigger, vn-updates before "
                       "the targets, target-updates within d_MMT + 2d_v, CNs on target and VNs "
                       "alive at each round start (seed 002 §V-B)"},
      {"y-consistency", "VNs that compute targets in the same round agree on the counts they "
                        "share (seed 002 §VI, line 232)"},
      {"round-refinement", "at every round start the counts per zone are the round-level "
                           "system's from the round start before (assign per zone; "
                           "docs/design/vn-layer.md §5.3, check 5)"},
      {"position-refinement", "at every round start each CN stands where the position-level "
                              "round system puts it from the round start before (assign and "
                              "calctarget per zone on the CNs' points; it follows V4's "
                              "migration, which round-refinement stops at)"},
      {"cn-reports", "no active CN holds a round counter in a past round, so every active CN "
                     "reports in every round (the premise of Theorem 1(2); cn_fail=keep "
                     "breaks it)"},
      {"stabilisation", "Theorem 1 round by round: on every execution the assignment becomes "
                        "fixed (T_stab) within Lemma 6's proportionality bound, and every CN "
                        "in a zone with q_h != 0 is on Gamma_h from round T_stab + 2 on (seed "
                        "002 §VI, lines 236, 302); worst T_out and T_stab beside the "
                        "round-level system's, and the distance to even spacing in the limit "
                        "(Lemma 7, measured) (docs/design/vn-layer.md §5.3, check 6)"},
      {"round-closure", "L_round (ours: the CNs on their targets, the VNs idle and VLBcast empty "
                        "at a round start) is reached at time delta from the start states, "
                        "closed from round start to round start, and free of time-locks "
                        "(docs/design/vn-layer.md §5.3, check 4)"}};
  d.check_params = [](const ParamValues& p) -> std::optional<std::string> {
    if (p.at("nbh") != 4 && p.at("nbh") != 8)
      return "nbh must be 4 or 8, not " + p.at("nbh").text();
    return vn_layer::invalid(vn_layer_config(p));
  };
  d.build = [](const ParamValues& p) {
    vn_layer::VnConfig c = vn_layer_config(p);
    c.branch_tally = std::make_shared<vlayer_mc::BranchTally>();
    const vn_layer::Lattice lattice = c.lattice();
    const tioa::Automaton layer = vn_layer::vn_layer(c, p.at("cn_faults") == 1);
    std::vector<vn_layer::Point> corner(static_cast<std::size_t>(c.cns),
                                        lattice.point(0, lattice.height() - 1));
    const tioa::StartSet start = p.at("start").text() == "corner"
                                     ? vn_layer::placed_start(layer, c, corner)
                                     : vn_layer::every_placement(layer, c);
    ModelInstance m{tioa::Start(layer, start), {}, "1 time unit"};
    const tioa::Automaton system = m.system;
    checker::Property no_timelock =
        custom_property("no-timelock", "every reachable state has an action or a tick",
                        [=](const checker::ExploreOptions& o) {
                          checker::PropertyResult r = checker::check_no_deadlock(system, o);
                          vn_layer::note_round_rules(c, r);
                          return r;
                        });
    no_timelock.fingerprint_store = true;
    m.properties = {
        std::move(no_timelock),
        custom_property("round-timing", "(T1)-(T4) of seed 002 §V-B on every reachable state",
                        [=](const checker::ExploreOptions& o) {
                          return vn_layer::check_round_timing(c, system, o);
                        }),
        custom_property("y-consistency", "y_f(h) = y_g(h) for VNs computing in one round (002:232)",
                        [=](const checker::ExploreOptions& o) {
                          return vn_layer::check_y_consistency(c, system, o);
                        }),
        custom_property("round-refinement",
                        "counts at each round start = the round-level system's from the one before",
                        [=, cn_faults = p.at("cn_faults") == 1](const checker::ExploreOptions& o) {
                          return vn_layer::check_round_refinement(c, system, o, cn_faults);
                        }),
        custom_property("position-refinement",
                        "points at each round start = the position-level system's from the one "
                        "before",
                        [=, cn_faults = p.at("cn_faults") == 1](const checker::ExploreOptions& o) {
                          return vn_layer::check_position_refinement(c, system, o, cn_faults);
                        }),
        custom_property("cn-reports", "no active CN with a round counter in the past",
                        [=](const checker::ExploreOptions& o) {
                          return vn_layer::check_cn_reports(c, system, o);
                        }),
        custom_property("stabilisation",
                        "the assignment becomes fixed, and C_in is on Gamma by T_stab + 2",
                        [=, cn_faults = p.at("cn_faults") == 1](const checker::ExploreOptions& o) {
                          return vn_layer::check_stabilisation(c, system, o, cn_faults);
                        })};
    checker::Property closure = custom_property(
        "round-closure", "L_round reached at delta, closed by rounds, without time-locks",
        [=, cn_faults = p.at("cn_faults") == 1](const checker::ExploreOptions& o) {
          return vn_layer::check_round_closure(c, layer, system, o, cn_faults);
        });
    const auto legal = std::make_shared<const vn_layer::RoundLegalSet>(layer, c);
    closure.predicate = [legal](const tioa::State& s) { return legal->contains(s.words()); };
    closure.predicate_name = "L_round";
    m.properties.push_back(std::move(closure));
    for (checker::Property& property : m.properties)
      property = counting_fig7(std::move(property), c.branch_tally);
    // The traces of round-closure's (b) and (c) start in L_round.
    m.trace_systems.emplace(vn_layer::l_round_system_name,
                            TraceSystem{vn_layer::l_round_layer(layer, c),
                                        "L_round (proofs/vn_layer/round_legal_set.hpp)",
                                        [legal](const tioa::Word* state) -> std::optional<bool> {
                                          return legal->contains(state);
                                        }});
    return m;
  };
  // 2×1 with 2 CNs at every placement (a second each); then from the corner, what breaks:
  // δ = 12 meets the paper's round rule but not the lattice's (README finding V1), ε = 0
  // lets a cn-update come after the exchange-trigger (C14), and a VN that may fail with CNs
  // in its zone breaks (Y) (C10, finding V2). The layer follows the round-level system on
  // 2×1; on 1×2 (from the corner) and 2×2 (every placement, 1.5 s each) calctarget sends
  // a CN onto the border the next zone owns (V4), which owned_ends=1 avoids. A CN that keeps
  // its variables when it fails (seed 001, cn_fail=keep) can be silent for ever (V5). At
  // position level the layer follows the round system across borders too, and δ = 12
  // drops a move (V1).
  // Theorem 1 round by round: the assignment settles and C_in is on Γ by T_stab + 2, also
  // across V4's migration on 1×2; a VN that may fail with a CN in its zone (vn_fail=any) can
  // keep that CN off Γ for ever (V6).
  const auto corner = [](ParamValues p) {
    p.emplace("start", ParamValue::choice("corner"));
    return p;
  };
  d.suite = {
      {{}, "no-timelock", checker::Verdict::holds},
      {{}, "round-timing", checker::Verdict::holds},
      {{}, "y-consistency", checker::Verdict::holds},
      {corner({{"delta", 12}}), "round-timing", checker::Verdict::violated},
      {corner({{"eps", 0}}), "round-timing", checker::Verdict::violated},
      {corner({{"vn_fail", ParamValue::choice("any")}}), "y-consistency",
       checker::Verdict::violated},
      {{}, "round-refinement", checker::Verdict::holds},
      {corner({{"rows", 1}, {"cols", 2}}), "round-refinement", checker::Verdict::violated},
      {corner({{"rows", 1}, {"cols", 2}, {"owned_ends", 1}}), "round-refinement",
       checker::Verdict::holds},
      {{{"rows", 2}, {"cols", 2}}, "round-refinement", checker::Verdict::violated},
      {{{"rows", 2}, {"cols", 2}, {"owned_ends", 1}}, "round-refinement", checker::Verdict::holds},
      {{}, "cn-reports", checker::Verdict::holds},
      {corner({{"cn_faults", 1}, {"cn_fail", ParamValue::choice("keep")}}), "cn-reports",
       checker::Verdict::violated},
      {{}, "position-refinement", checker::Verdict::holds},
      {{{"rows", 2}, {"cols", 2}}, "position-refinement", checker::Verdict::holds},
      {corner({{"delta", 12}}), "position-refinement", checker::Verdict::violated},
      {{}, "stabilisation", checker::Verdict::holds},
      {{{"rows", 1}, {"cols", 2}}, "stabilisation", checker::Verdict::holds},
      // Three CNs in one zone of side 4: the middle one settles a unit short (Lemma 7).
      {corner({{"rows", 1}, {"cns", 3}, {"b", 4}}), "stabilisation", checker::Verdict::holds},
      {{{"cns", 1}, {"vn_fail", ParamValue::choice("any")}},
       "stabilisation",
       checker::Verdict::violated},
      // L_round (ours) is reached at delta, closed from round start to round start and free
      // of time-locks when delta meets the lattice's rule, also across V4's migration on
      // 1x2; at delta = 12 a CN reaches a zone whose VN restarts only after the round start.
      {{}, "round-closure", checker::Verdict::holds},
      {{{"rows", 1}, {"cols", 2}}, "round-closure", checker::Verdict::holds},
      {corner({{"delta", 12}}), "round-closure", checker::Verdict::violated}};
  return d;
}

} // namespace catalogue
