#include "catalogue/vn_emulation.hpp"

#include "models/vn_emulation/emulation.hpp"
#include "proofs/vn_emulation/emulation_checks.hpp"

namespace catalogue {

vn_emulation::EmuConfig vn_emulation_config(const ParamValues& p) {
  vn_emulation::EmuConfig c;
  c.zones = whole(p, "zones");
  c.rp2 = whole(p, "rp2");
  c.moves = whole(p, "moves");
  c.pns = whole(p, "pns");
  c.d_p = whole(p, "d_p");
  c.eps = whole(p, "eps");
  c.messages = whole(p, "messages");
  c.fails = whole(p, "fails");
  c.buffer = whole(p, "buffer");
  c.start = p.at("start").text() == "cold" ? vn_emulation::Start::cold : vn_emulation::Start::warm;
  c.inputs = p.at("inputs").text() == "ticks" ? vn_emulation::Inputs::ticks
                                              : vn_emulation::Inputs::anywhere;
  c.record_always = p.at("record").text() == "always";
  c.quiescent_ack = p.at("ack").text() == "quiescent";
  c.printed_init_action = p.at("init_action").text() == "printed";
  c.printed_restart = p.at("restart").text() == "printed";
  const std::string vn = p.at("vn").text();
  c.vn = vn == "report" ? vn_emulation::Vn::report
         : vn == "mc"   ? vn_emulation::Vn::mc
                        : vn_emulation::Vn::fifo;
  c.ties =
      p.at("ties").text() == "content" ? vn_emulation::Ties::content : vn_emulation::Ties::arrival;
  c.reset_joined = p.at("reset").text() == "joined";
  c.tobcast_zone_at_delivery = p.at("tobcast_zone").text() == "delivery";
  return c;
}

namespace {
// A choice whose default is the paper's reading and whose other value repairs a finding.
ParamSpec repair_choice(std::string name, std::string paper, std::string repair,
                        std::string description) {
  ParamSpec p =
      ParamSpec::choice(std::move(name), paper, {paper, std::move(repair)}, std::move(description));
  p.variant = true;
  return p;
}
} // namespace

ModelDefinition vn_emulation_definition() {
  ModelDefinition d;
  d.name = "vn-emulation";
  d.description = "the VN emulation of seed 002 §VIII: physical nodes running TOBcast and VNE "
                  "(join, reset) over LBcast(d_p) in one zone or two, emulating a FIFO-counter VN; "
                  "Theorem 2's figures (time: quanta; models/vn_emulation/README.md)";
  d.params = {
      {"zones", 1, 1, 2,
       "1: one zone, no geometry (instance I1); 2: two zones side by side on a 4 x 2 lattice, "
       "the PNs moving, LBcast bounded by R_p (I2 with pns=2, I3 with pns=3)"},
      {"pns", 2, 1, 3, "physical nodes (two zones: the last starts in zone 1)"},
      {"rp2", 20, 1, 40,
       "two zones: R_p squared in lattice units squared, b = 2 (the paper's R_p >= sqrt(5) b "
       "is 20)"},
      {"moves", 2, 0, 4, "two zones: lattice steps the PNs make in all"},
      {"d_p", 1, 1, 3, "LBcast's delay bound d_p"},
      {"eps", 1, 0, 3, "TOBcast's extra hold eps (seed 002 line 348)"},
      {"messages", 1, 0, 3, "client messages sent in all"},
      {"fails", 1, 0, 3, "fail inputs in all (a failed node may recover at any time)"},
      {"buffer", 6, 2, vn_emulation::EmuConfig::max_buffer_capacity,
       "the model's bound on TOBcast's hold buffer, entries per PN (a check that meets it is "
       "incomplete: raise it to check beyond)"},
      ParamSpec::choice("start", "warm", {"warm", "cold"},
                        "warm: every VNE active in the zone at time 0; cold: as printed "
                        "(h = ⊥, every VN starts failed)"),
      ParamSpec::choice("inputs", "anywhere", {"anywhere", "ticks"},
                        "when sends, fails and recovers happen: between any two steps, or only "
                        "where time may pass"),
      ParamSpec::choice("record", "executed", {"executed", "always"},
                        "simulate-action records a key in completed-actions only when it "
                        "executes it (the OCR's indentation lost, D9) or always"),
      ParamSpec::choice("ack", "quiescent", {"quiescent", "any"},
                        "ack-join waits until no VN action is enabled (as printed, line 456) "
                        "or not"),
      ParamSpec::choice("init_action", "once", {"once", "printed"},
                        "init-action suggests each action once per VN state (D6, the intent of "
                        "line 358) or as printed (lines 420-424: its precondition stays true, "
                        "so time never passes again, F1)"),
      ParamSpec::choice("restart", "once", {"once", "printed"},
                        "a joiner's restart sends one reset (D7) or as printed (lines 430-434: "
                        "its precondition stays true, F1)"),
      ParamSpec::choice("tobcast_zone", "arrival", {"arrival", "delivery"},
                        "two zones: TOBcast drops a packet of another zone than its PN's when "
                        "it arrives and empties its buffer on a zone change (D13), or keeps "
                        "every packet and drops one of another zone at its delivery"),
      ParamSpec::choice("vn", "fifo", {"fifo", "report", "mc"},
                        "the VN emulated: a FIFO counter that sends from a queue (as Fig. 6's "
                        "VN), one whose send reports the current count (F3), or the MC VN of "
                        "Fig. 6 itself (vn-layer's VN; each CN sends its round's cn-update, "
                        "exchange-trigger and target-trigger in that order)"),
      // E4: the paper's TOBcast orders one timestamp's messages by sender and sequence
      // number only (002:348).
      repair_choice("ties", "arrival", "content",
                    "two TOBcast messages with one tag (a PN that failed and recovered in the "
                    "instant) in each PN's order of arrival, as the paper leaves them (E4), or "
                    "a repair: by content"),
      // E5: as printed (002:352) a VNE takes a reset whatever its status.
      repair_choice("reset", "any", "joined",
                    "a VNE takes a reset whatever its status, as printed (D5; E5), or a "
                    "repair: only once its own join-req is delivered (listening) or when "
                    "active")};
  d.properties = {
      {"no-timelock", "every reachable state has an action or a tick"},
      {"replica-consistency", "where time passes, the active replicas hold the same VN state "
                              "(seed 002 §VIII)"},
      {"theorem-2", "Theorem 2's d_MMT = 2d_p + 2eps, d_r = 4d_p + 5eps and d_v = 2d_p + eps, "
                    "measured as worst cases against the stated ones"},
      {"refines-vn", "the emulation implements the abstract VN: every event it maps to the VN's "
                     "actions is one the VN can take, and the replicas hold the VN's state"},
      {"no-live-restart", "no reset restarts the VN while it is alive (P6; F4 of "
                          "docs/design/vn-emulation.md)"}};
  d.check_params = [](const ParamValues& p) -> std::optional<std::string> {
    return vn_emulation::invalid(vn_emulation_config(p));
  };
  d.build = [](const ParamValues& p) {
    const vn_emulation::EmuConfig c = vn_emulation_config(p);
    const vn_emulation::Emulation e = vn_emulation::emulation(c);
    ModelInstance m{e.automaton, {}, "1 time unit"};
    const auto slots = e.slots;
    m.beyond_bound = [slots](const tioa::State& s) { return slots->past_bound(s); };
    m.bound_name = "the model's bounds on its queues and sets (models/vn_emulation/config.hpp)";
    checker::Property no_timelock = custom_property(
        "no-timelock", "every reachable state has an action or a tick",
        [=](const checker::ExploreOptions& o) { return vn_emulation::check_no_timelock(e, o); });
    checker::Property replicas =
        custom_property("replica-consistency", "the active replicas agree where time passes",
                        [=](const checker::ExploreOptions& o) {
                          return vn_emulation::check_replica_consistency(e, o);
                        });
    // P7 and theorem-2 run on emulations with their monitors' ghosts, built when the
    // check runs.
    vn_emulation::EmuConfig monitored = c;
    monitored.refinement_monitor = true;
    vn_emulation::EmuConfig delivered = c;
    delivered.delivery_monitor = true;
    // Every check also runs on the fingerprint store.
    no_timelock.fingerprint_store = true;
    replicas.fingerprint_store = true;
    checker::Property refines = custom_property(
        "refines-vn",
        "the emulation's events are the abstract VN's, and the replicas hold its state",
        [=](const checker::ExploreOptions& o) {
          return vn_emulation::check_refinement(vn_emulation::emulation(monitored), o);
        });
    refines.fingerprint_store = true;
    checker::Property no_live_restart = custom_property(
        "no-live-restart", "no reset restarts a live VN", [=](const checker::ExploreOptions& o) {
          return vn_emulation::check_no_live_restart(vn_emulation::emulation(monitored), o);
        });
    no_live_restart.fingerprint_store = true;
    checker::Property theorem = custom_property(
        "theorem-2", "Theorem 2's figures against the stated ones",
        [=](const checker::ExploreOptions& o) {
          return vn_emulation::check_theorem_2(vn_emulation::emulation(delivered), o);
        });
    theorem.fingerprint_store = true;
    m.properties = {std::move(no_timelock), std::move(replicas), std::move(theorem),
                    std::move(refines), std::move(no_live_restart)};
    return m;
  };
  // Warm start with one message and one fail; a cold start, where the VN starts exactly
  // d_r = 4d_p + 5eps after time 0 (README). E1 (d_v broken) and F4 (a live VN restarted)
  // need two fails and tens of seconds: they are tests, not suite entries.
  d.suite = {{{}, "no-timelock", checker::Verdict::holds},
             {{}, "replica-consistency", checker::Verdict::holds},
             {{}, "theorem-2", checker::Verdict::holds},
             {{}, "refines-vn", checker::Verdict::holds},
             {{}, "no-live-restart", checker::Verdict::holds},
             {{{"start", ParamValue::choice("cold")}, {"messages", 0}, {"fails", 0}},
              "theorem-2",
              checker::Verdict::holds},
             // F1: restart as printed time-locks the cold start at 7 (README "Readings").
             {{{"start", ParamValue::choice("cold")},
               {"messages", 0},
               {"fails", 0},
               {"restart", ParamValue::choice("printed")}},
              "no-timelock",
              checker::Verdict::violated},
             // Two zones, one PN each, no motion: every figure within Theorem 2's with
             // R_p^2 = 20; with 9 a VN's message misses the far corner of the other zone.
             {{{"zones", 2}, {"fails", 0}, {"moves", 0}}, "theorem-2", checker::Verdict::holds},
             {{{"zones", 2}, {"fails", 0}, {"moves", 0}, {"rp2", 9}},
              "theorem-2",
              checker::Verdict::violated},
             // F3: a VN whose send reports its current value misses d_MMT (6 > 4).
             {{{"pns", 1}, {"messages", 3}, {"fails", 0}, {"vn", ParamValue::choice("report")}},
              "theorem-2",
              checker::Verdict::violated},
             // The MC VN of Fig. 6 emulated (README "The MC VN"): one fail; and one PN
             // whose CN sends its whole round, so that the VN sends a vn-update and a
             // target-update.
             {{{"vn", ParamValue::choice("mc")}}, "replica-consistency", checker::Verdict::holds},
             {{{"pns", 1}, {"messages", 3}, {"fails", 0}, {"vn", ParamValue::choice("mc")}},
              "theorem-2",
              checker::Verdict::holds}};
  return d;
}

} // namespace catalogue
