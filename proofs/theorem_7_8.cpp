#include "proofs/theorem_7_8.hpp"

#include <algorithm>
#include <array>

namespace vlayer_mc {

namespace {

using checker::PropertyResult;
using checker::Verdict;

struct Part {
  const PropertyResult* result;
  const char* name; // the property
  const char* role; // what it contributes to the theorem
};

} // namespace

PropertyResult theorem_7_8(const PropertyResult& theorem_7_5, const PropertyResult& lemma_7_6,
                           const PropertyResult& lemma_7_7) {
  const std::array<Part, 3> parts{{
      {&theorem_7_5, "theorem-7.5", "into LMC within delta + d + e + eps_sample (Theorem 7.5)"},
      {&lemma_7_7, "lemma-7.7",
       "every ResetMC state R_MC-related to a reachable state (Lemma 7.7)"},
      {&lemma_7_6, "lemma-7.6", "R_MC a simulation relation (Lemma 7.6)"},
  }};
  const auto violated = std::find_if(parts.begin(), parts.end(), [](const Part& p) {
    return p.result->verdict == Verdict::violated;
  });

  // A violated part gives its counterexample: its trace, witnesses and notes.
  PropertyResult r = violated != parts.end() ? *violated->result : PropertyResult{};
  r.name = "theorem-7.8";
  if (violated == parts.end()) // else the failing part's kind, which its trace is of
    r.kind = "composition";
  r.description = "Theorem 7.8 of seed 000 (§7.3): from an arbitrary state with "
                  "R(Vbcast||RW||VW), the traces are, from delta + d + e + eps_sample on, "
                  "reachable traces of R(VLayer[MC]); by Theorem 7.5, Lemma 7.7 and Lemma 7.6";
  r.states = r.edges = 0;
  r.seconds = 0;
  r.threads = 1;
  // The theorem quantifies over arbitrary start states, as Theorem 7.5 does; the other parts'
  // coverage is in the notes.
  r.coverage = theorem_7_5.coverage;
  for (const Part& p : parts) {
    r.states += p.result->states;
    r.edges += p.result->edges;
    r.seconds += p.result->seconds;
    r.threads = std::max(r.threads, p.result->threads);
  }
  std::vector<std::string> parts_notes;
  for (const Part& p : parts)
    parts_notes.push_back(std::string(p.name) + " " + checker::to_string(p.result->verdict) + " (" +
                          p.role + "): " + p.result->message + "; coverage " +
                          checker::describe(p.result->coverage));
  if (violated != parts.end()) {
    r.verdict = Verdict::violated;
    r.message = "violated: the step '" + std::string(violated->role) + "' fails (" +
                violated->name + ": " + violated->result->message + ")";
  } else if (std::all_of(parts.begin(), parts.end(),
                         [](const Part& p) { return p.result->verdict == Verdict::holds; })) {
    r.verdict = Verdict::holds;
    r.message = "holds: Theorem 7.5, Lemma 7.7 and Lemma 7.6 all hold on this instance";
  } else {
    r.verdict = Verdict::incomplete;
    std::string open;
    for (const Part& p : parts)
      if (p.result->verdict != Verdict::holds)
        open += std::string(open.empty() ? "" : ", ") + p.name;
    r.message = "incomplete: no step fails, but " + open +
                " did not cover its whole statement, so the composition does not either";
  }
  r.notes.insert(r.notes.begin(), parts_notes.begin(), parts_notes.end());
  r.notes.insert(r.notes.begin(),
                 "statement: seed 000 Theorem 7.8 (lines 1336-1338), by composition as the "
                 "paper argues it (lines 1300-1335)");
  r.figures.insert(r.figures.begin(), {{"theorem-7.5", checker::to_string(theorem_7_5.verdict)},
                                       {"lemma-7.7", checker::to_string(lemma_7_7.verdict)},
                                       {"lemma-7.6", checker::to_string(lemma_7_6.verdict)}});
  return r;
}

} // namespace vlayer_mc
