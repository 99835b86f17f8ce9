#include "models/mc/positions.hpp"

#include <algorithm>
#include <random>
#include <sstream>
#include <stdexcept>

#include "models/mc/spacing.hpp"

namespace mc {

namespace {

std::vector<QuantisedLength> quantised(const ExactCurve& curve) {
  const auto& q = curve.on_grid().q();
  return {q.begin(), q.end()};
}

// A Fisher–Yates shuffle driven by mt19937_64 seeded through seed_seq: both are specified
// exactly by the standard, so the order is the same with every standard library
// (std::shuffle and the distributions are not). The modulo bias is irrelevant here.
void shuffle(std::vector<std::size_t>& items, std::uint64_t seed, std::size_t round, RegionId h) {
  std::seed_seq sequence{static_cast<std::uint32_t>(seed), static_cast<std::uint32_t>(seed >> 32),
                         static_cast<std::uint32_t>(round), static_cast<std::uint32_t>(h)};
  std::mt19937_64 engine(sequence);
  for (std::size_t i = items.size(); i > 1; --i)
    std::swap(items[i - 1], items[engine() % i]);
}

} // namespace

PositionSystem::PositionSystem(ExactCurve curve, McParams params, PositionOptions options)
    : curve_(std::move(curve)), counts_(curve_.grid(), quantised(curve_), std::move(params)),
      options_(options) {}

void PositionSystem::check_robots(const std::vector<Robot>& robots) const {
  const Rational side = curve_.grid().m() * curve_.on_grid().b();
  for (std::size_t i = 0; i < robots.size(); ++i) {
    const Robot& robot = robots[i];
    if (i > 0 && robots[i - 1].id >= robot.id)
      throw std::invalid_argument(
          "robot ids must be distinct and increasing: " + std::to_string(robots[i - 1].id) +
          " before " + std::to_string(robot.id));
    const RationalPoint& p = robot.position;
    if (p.x < 0 || p.y < 0 || p.x > side || p.y > side)
      throw std::invalid_argument("robot " + std::to_string(robot.id) + " at " + to_string(p) +
                                  " lies outside the deployment square [0, " + to_string(side) +
                                  "]^2");
    if (robot.assigned && *robot.assigned >= curve_.size())
      throw std::invalid_argument("robot " + std::to_string(robot.id) + " is assigned to region " +
                                  std::to_string(*robot.assigned) + ", which does not exist");
  }
}

RegionId PositionSystem::member_of(const Robot& robot) const {
  if (options_.membership == Membership::assigned && robot.assigned &&
      curve_.in_closure(*robot.assigned, robot.position))
    return *robot.assigned;
  return curve_.region_of(robot.position);
}

std::vector<Target> PositionSystem::calctarget(RegionId h, const std::vector<Robot>& members,
                                               const std::vector<RegionId>& assigned) const {
  if (members.size() != assigned.size())
    throw std::invalid_argument("calctarget: one assignment per member");
  std::vector<Target> targets(members.size());
  // Line 27: seq, the staying robots on Γ_h as ⟨p, i⟩ sorted by p, then i.
  struct Entry {
    Rational parameter;
    RobotId id;
    std::size_t index;
  };
  std::vector<Entry> seq;
  for (std::size_t i = 0; i < members.size(); ++i) {
    const Robot& robot = members[i];
    Target& target = targets[i];
    target.robot = robot.id;
    target.assigned = assigned[i];
    if (assigned[i] != h) { // lines 30–31
      target.position = curve_.centre(assigned[i]);
      target.rule = TargetRule::centre;
    } else if (!curve_.meets(h)) {
      // Decision: Γ_h = ∅ (h off the curve, q_h = 0) leaves line 33's min over ∅
      // undefined; the robot keeps its position (it stays in R_h, as a member of VN_h).
      target.position = robot.position;
      target.rule = TargetRule::off_curve;
    } else if (auto p = curve_.parameter(h, robot.position)) {
      seq.push_back({std::move(*p), robot.id, i});
    } else { // lines 32–33, ties to the smallest parameter
      target.position = curve_.nearest(h, robot.position).point;
      target.rule = TargetRule::nearest;
    }
  }
  std::sort(seq.begin(), seq.end(), [](const Entry& a, const Entry& b) {
    return a.parameter != b.parameter ? a.parameter < b.parameter : a.id < b.id;
  });
  std::vector<Rational> sorted;
  for (const Entry& entry : seq)
    sorted.push_back(entry.parameter);
  // Lines 35–38 in the local parameter: P_h = [0, |A_h|].
  const std::vector<Rational> next =
      spacing_step(sorted, Rational(0), curve_.length(h), counts_.params().rho1);
  for (std::size_t k = 0; k < seq.size(); ++k) {
    Target& target = targets[seq[k].index];
    target.position = curve_.point(h, next[k]);
    target.rule =
        k == 0 ? TargetRule::first : (k + 1 == seq.size() ? TargetRule::last : TargetRule::spacing);
  }
  return targets;
}

PositionRound PositionSystem::round(const std::vector<Robot>& robots, std::size_t t) const {
  check_robots(robots);
  PositionRound record;
  record.round = t;
  record.robots = robots;
  record.counts.assign(curve_.size(), 0);
  std::vector<std::vector<std::size_t>> of_region(curve_.size());
  for (std::size_t i = 0; i < robots.size(); ++i) {
    const RegionId h = member_of(robots[i]);
    record.members.push_back(h);
    ++record.counts[h];
    of_region[h].push_back(i); // by increasing id
  }
  record.flow = counts_.flow(record.counts);
  record.targets.resize(robots.size());

  for (RegionId h = 0; h < curve_.size(); ++h) {
    std::vector<std::size_t>& indices = of_region[h];
    if (indices.empty())
      continue;
    if (options_.reassignment == Reassignment::random)
      shuffle(indices, options_.seed, t, h);
    // Line 11: the first ra robots (in the rule's order) to the first g of the flow, …
    std::vector<RegionId> assigned(indices.size(), h);
    std::size_t next = 0;
    for (const Transfer& transfer : record.flow.transfers) {
      if (transfer.from != h)
        continue;
      for (RobotCount r = 0; r < transfer.robots; ++r, ++next) {
        assigned[next] = transfer.to;
        record.reassigned.push_back({robots[indices[next]].id, h, transfer.to});
      }
    }
    std::vector<Robot> members;
    for (std::size_t i : indices)
      members.push_back(robots[i]);
    const std::vector<Target> targets = calctarget(h, members, assigned);
    for (std::size_t k = 0; k < indices.size(); ++k)
      record.targets[indices[k]] = targets[k];
  }
  std::sort(record.reassigned.begin(), record.reassigned.end(),
            [](const Move& a, const Move& b) { return a.robot < b.robot; });

  for (const Target& target : record.targets) {
    const RegionId next = member_of({target.robot, target.position, target.assigned});
    if (next != target.assigned)
      record.migrations.push_back({target.robot, target.assigned, next});
  }
  return record;
}

std::vector<Robot> PositionSystem::after(const PositionRound& round) {
  std::vector<Robot> robots;
  for (const Target& target : round.targets)
    robots.push_back({target.robot, target.position, target.assigned});
  return robots;
}

// Round t certifies that the assignment is fixed from t on when assign moves nobody in
// round t, nobody migrates in round t, and (under Membership::position) no robot will
// ever be sent to a boundary point its region does not own. Then by induction on t' ≥ t:
// the counts at the start of t' are those of t (no reassignment, no migration), so assign
// moves nobody in t' (the flow is a function of the counts). After round t every robot
// of a region h that meets Γ stands on the closure of Γ_h (line 33 puts the ones off Γ_h
// on it; lines 35–38 keep the ones on it there), so from round t+1 on all n_h of them are
// in seq: one goes to Γ_h(inf P_h) (line 35), for n_h ≥ 2 one to Γ_h(sup P_h) (line 36),
// and the others to p + ρ1·((p_{k−1} + p_{k+1})/2 − p), a convex combination of
// p_{k−1}, p_k, p_{k+1} (weights ρ1/2, 1 − ρ1, ρ1/2 ≥ 0 for ρ1 ≤ 1), so within
// [inf P_h, sup P_h]. P_h is an interval of points owned by h except possibly its ends,
// so only a non-owned end can take a robot out of R_h: inf when n_h ≥ 1, sup when
// n_h ≥ 2; the condition below excludes exactly those. (If it fails, round t+1 sends a
// robot there, so the certificate is also necessary once the flow is empty.) A robot in a
// region off Γ keeps its position. Under Membership::assigned a member of h stands in the
// closed square of h and every target of a staying robot lies there too, so membership
// never changes once assign moves nobody: the first two conditions suffice.
bool PositionSystem::certifies_fixed(const PositionRound& round) const {
  if (!round.flow.empty() || !round.migrations.empty())
    return false;
  if (options_.membership == Membership::assigned)
    return true;
  for (RegionId h = 0; h < curve_.size(); ++h) {
    const RobotCount n = round.counts[h];
    if (n == 0 || !curve_.meets(h))
      continue;
    const ExactLocalPart& part = curve_.local(h);
    if (!part.inf_owned || (n >= 2 && !part.sup_owned))
      return false;
  }
  return true;
}

PositionRun PositionSystem::run(std::vector<Robot> start, std::size_t rounds) const {
  PositionRun result;
  result.last = std::move(start);
  for (std::size_t t = 0; t < rounds; ++t) {
    result.rounds.push_back(round(result.last, t));
    result.last = after(result.rounds.back());
    if (!result.fixed_from && certifies_fixed(result.rounds.back()))
      result.fixed_from = t;
  }
  return result;
}

std::string format_round(const PositionRound& round) {
  std::ostringstream out;
  out << "round " << round.round << ": counts";
  for (RobotCount c : round.counts)
    out << ' ' << c;
  out << "; flow";
  if (round.flow.empty())
    out << " none";
  for (const Transfer& transfer : round.flow.transfers)
    out << ' ' << transfer.from << "->" << transfer.to << ':' << transfer.robots;
  out << "; reassigned";
  if (round.reassigned.empty())
    out << " none";
  for (const Move& move : round.reassigned)
    out << " #" << move.robot << ' ' << move.from << "->" << move.to;
  out << "; migrations";
  if (round.migrations.empty())
    out << " none";
  for (const Move& move : round.migrations)
    out << " #" << move.robot << ' ' << move.from << "->" << move.to;
  out << '\n';
  for (std::size_t i = 0; i < round.robots.size(); ++i)
    out << "  #" << round.robots[i].id << " at " << to_string(round.robots[i].position) << " VN "
        << round.members[i] << " -> " << to_string(round.targets[i].position) << '\n';
  return out.str();
}

} // namespace mc
