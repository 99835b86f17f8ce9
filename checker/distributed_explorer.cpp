#include "checker/distributed_explorer.hpp"

#include <algorithm>
#include <chrono>
#include <cstring>

#include "checker/interrupt.hpp"
#include "checker/memory_budget.hpp"
#include "checker/state_store.hpp"

namespace checker {

namespace {

// A discovery key: the id of the state a successor was found from and the index of its
// step there (discovery.hpp); a start state's is its place in the start set's enumeration,
// with the top bit set, so that start states come first and in that order.
constexpr std::uint64_t start_key_bit = std::uint64_t{1} << 63;
std::uint64_t step_key(std::uint64_t from, std::uint32_t step) {
  return from << 32 | step;
}
constexpr std::uint32_t no_id = 0xffffffffu;

// Frontier states a rank expands before an exchange: bounds what a round sends.
constexpr std::size_t round_states = 1 << 14;
// Start states every rank enumerates between two looks at the limits.
constexpr std::uint64_t start_round = 1 << 16;

// One rank's states: its store, and for each state (by local id) its discovery key and its
// id in the whole run (no_id until its level is numbered).
struct RankStates {
  explicit RankStates(std::uint32_t words) : store(words) {}
  StateStore store;
  std::vector<std::uint64_t> key;
  std::vector<std::uint32_t> id;
  std::vector<std::pair<std::uint32_t, StateId>> by_id; // (id, local id), ids increasing

  // Inserts a state found with `k`; a state of the level being built keeps its smallest
  // key. Returns its local id when it is new.
  std::optional<StateId> offer(const Word* state, std::uint64_t k) {
    const auto [local, fresh] = store.insert(state, hash_state(state, store.words()));
    if (fresh) {
      key.push_back(k);
      id.push_back(no_id);
      return local;
    }
    if (id[local] == no_id)
      key[local] = std::min(key[local], k);
    return std::nullopt;
  }
};

// Numbers the level's new states (local ids `fresh`) as one process would: by their keys
// among every rank's; `first` is the id of the level's first state. Returns the level's
// size over all ranks and leaves `fresh` in id order.
std::uint64_t number_level(RankStates& rs, std::vector<StateId>& fresh, std::uint64_t first,
                           Collective& ranks) {
  std::sort(fresh.begin(), fresh.end(),
            [&](StateId a, StateId b) { return rs.key[a] < rs.key[b]; });
  std::vector<std::uint8_t> mine;
  mine.reserve(fresh.size() * 8);
  for (StateId s : fresh)
    append_bytes(mine, &rs.key[s], 8);
  std::vector<std::uint64_t> sizes;
  const std::vector<std::uint8_t> all = ranks.all_gather(mine, sizes);
  std::uint64_t total = 0;
  for (std::uint64_t bytes : sizes)
    total += bytes / 8;
  // Each of my keys' place: how many keys of every rank are smaller (keys are unique).
  std::vector<std::uint64_t> place(fresh.size(), 0);
  std::size_t at = 0;
  for (std::uint64_t bytes : sizes) {
    const std::size_t n = bytes / 8;
    std::size_t j = 0;
    for (std::size_t i = 0; i < fresh.size(); ++i) {
      const std::uint64_t k = rs.key[fresh[i]];
      while (j < n) {
        std::uint64_t other;
        std::memcpy(&other, all.data() + at + j * 8, 8);
        if (other >= k)
          break;
        ++j;
      }
      place[i] += j;
    }
    at += bytes;
  }
  for (std::size_t i = 0; i < fresh.size(); ++i) {
    const auto id = static_cast<std::uint32_t>(first + place[i]);
    rs.id[fresh[i]] = id;
    rs.by_id.emplace_back(id, fresh[i]);
  }
  return total;
}

// The smallest id among `fresh` whose state is a target, over all ranks (no_id: none).
std::uint64_t first_target(const RankStates& rs, const std::vector<StateId>& fresh,
                           const tioa::StatePredicate& target, Collective& ranks) {
  std::uint64_t found = no_id;
  if (target)
    for (StateId s : fresh)
      if (rs.id[s] < found && target(tioa::State(rs.store.state(s), 0)))
        found = rs.id[s];
  return ranks.min(found);
}

// The states from a start state to `id`, asking the owner of each in turn.
std::vector<std::vector<Word>> path_to(const RankStates& rs, std::uint64_t id, Collective& ranks) {
  const std::uint32_t words = rs.store.words();
  std::vector<std::vector<Word>> path;
  for (;;) {
    std::vector<std::uint8_t> mine;
    const auto it = std::lower_bound(rs.by_id.begin(), rs.by_id.end(),
                                     std::make_pair(static_cast<std::uint32_t>(id), StateId{0}));
    if (it != rs.by_id.end() && it->first == id) {
      append_bytes(mine, rs.store.state(it->second), words * sizeof(Word));
      append_bytes(mine, &rs.key[it->second], 8);
    }
    std::vector<std::uint64_t> sizes;
    const std::vector<std::uint8_t> all = ranks.all_gather(mine, sizes);
    if (all.size() != words * sizeof(Word) + 8)
      throw std::logic_error("distributed trace: state " + std::to_string(id) + " has " +
                             std::to_string(all.size()) + " bytes of owners");
    std::vector<Word> state(words);
    std::memcpy(state.data(), all.data(), words * sizeof(Word));
    std::uint64_t k;
    std::memcpy(&k, all.data() + words * sizeof(Word), 8);
    path.push_back(std::move(state));
    if (k & start_key_bit)
      break;
    id = k >> 32;
  }
  std::reverse(path.begin(), path.end());
  return path;
}

} // namespace

int owner_of(std::uint64_t hash, int ranks) {
  std::uint64_t h = hash ^ 0x5bd1e9955bd1e995u;
  h ^= h >> 33;
  h *= 0xff51afd7ed558ccdu;
  h ^= h >> 33;
  return static_cast<int>(h % static_cast<std::uint64_t>(ranks));
}

DistributedExploration explore_distributed(const tioa::SuccessorGenerator& generator,
                                           const tioa::StartSet& start,
                                           const ExploreOptions& options,
                                           const tioa::StatePredicate& target,
                                           const tioa::StatePredicate& ended, Collective& ranks) {
  const auto began = std::chrono::steady_clock::now();
  auto elapsed = [&] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
  };
  const Limits& limits = options.limits;
  const std::uint32_t words = generator.words();
  const int me = ranks.rank(), size = ranks.size();
  DistributedExploration out;
  // What the property's budget has left (options.hpp): nothing left, nothing explored.
  const std::uint64_t max_states = limits.states_left();
  if (limits.states_exhausted()) {
    out.stop = StopReason::state_limit;
    return out;
  }
  RankStates rs(words);
  std::size_t peak = 0;

  // Between rounds: any rank out of time or memory, or asked to stop, stops every rank.
  auto stop_now = [&]() -> std::optional<StopReason> {
    const std::uint64_t resident = resident_bytes();
    peak = std::max<std::size_t>(peak, resident);
    std::uint64_t reason = 0;
    if (interrupted())
      reason = 3;
    else if (resident_over_limit(limits)) // (as one process counts it, per rank)
      reason = 2;
    else if (limits.out_of_time(elapsed()))
      reason = 1;
    switch (ranks.max(reason)) {
    case 3:
      return StopReason::interrupted;
    case 2:
      return StopReason::memory_limit;
    case 1:
      return StopReason::time_limit;
    default:
      return std::nullopt;
    }
  };

  // After a level is numbered: its first target, or the state limit. A sequential search
  // keeps the first max_states states (ids below it) and goes on with the level for the
  // counts (expansion.hpp), so only a target among those counts.
  auto level_done = [&](const std::vector<StateId>& fresh) -> std::optional<StopReason> {
    const std::uint64_t found = first_target(rs, fresh, target, ranks);
    if (found != no_id && (!max_states || found < max_states)) {
      out.found = found;
      return StopReason::found;
    }
    if (max_states && out.states > max_states) {
      out.states = max_states;
      return StopReason::state_limit;
    }
    return std::nullopt;
  };

  // Level 0: every rank enumerates the start set and keeps the states it owns. Every
  // start_round states enumerated (the same on every rank) the ranks stop together at a
  // target, the state limit or a time or memory limit, as one process stops inserting them
  // (start_insertion.hpp): the states enumerated so far are there, so the ids are right.
  struct StopEnumeration {};
  std::vector<StateId> fresh;
  std::optional<StopReason> stop;
  {
    std::vector<Word> buffer(words + 1, 0);
    std::uint64_t index = 0, targets = 0;
    auto enough = [&]() -> bool {
      const bool found = ranks.max(targets) > 0;
      if (!found && max_states && ranks.sum(fresh.size()) > max_states)
        return true;
      if (!found)
        stop = stop_now();
      return found || stop;
    };
    try {
      start.enumerate(buffer.data(), 0, [&] {
        const std::uint64_t i = index++;
        if (owner_of(hash_state(buffer.data(), words), size) == me)
          if (const auto local = rs.offer(buffer.data(), start_key_bit | i)) {
            fresh.push_back(*local);
            if (target && target(tioa::State(buffer.data(), 0)))
              ++targets;
          }
        if (index % start_round == 0 && enough())
          throw StopEnumeration{};
      });
    } catch (const StopEnumeration&) {
    }
  }
  std::uint64_t level_first = 0;
  std::uint64_t level_size = stop ? 0 : number_level(rs, fresh, level_first, ranks);
  out.states = out.start_states = level_size;
  if (!stop)
    stop = level_done(fresh);
  if (!stop)
    stop = stop_now();

  std::vector<std::uint8_t> send, received;
  std::vector<std::vector<std::uint8_t>> to(static_cast<std::size_t>(size));
  std::vector<std::uint64_t> offsets(static_cast<std::size_t>(size) + 1);
  std::vector<Word> scratch(words + 1, 0);
  std::uint64_t first_stuck = no_id;
  const std::size_t record = words * sizeof(Word) + 8;
  while (level_size > 0 && !stop) {
    std::vector<StateId> frontier;
    frontier.swap(fresh);
    const std::uint64_t rounds = ranks.max((frontier.size() + round_states - 1) / round_states);
    for (std::uint64_t round = 0; round < rounds && !stop; ++round) {
      for (auto& t : to)
        t.clear();
      const std::size_t begin = std::min(frontier.size(), round * round_states);
      const std::size_t end = std::min(frontier.size(), begin + round_states);
      for (std::size_t f = begin; f < end; ++f) {
        const StateId s = frontier[f];
        const std::uint64_t from = rs.id[s];
        std::uint32_t step = 0;
        const std::size_t n = generator.successors(
            rs.store.state(s), scratch.data(), [&](const Word* succ, const tioa::StepLabel&) {
              const std::uint64_t k = step_key(from, step++);
              auto& t = to[static_cast<std::size_t>(owner_of(hash_state(succ, words), size))];
              append_bytes(t, succ, words * sizeof(Word));
              append_bytes(t, &k, 8);
            });
        out.edges += n;
        if (n > 0)
          continue;
        if (ended && ended(tioa::State(rs.store.state(s), 0))) {
          ++out.ended;
        } else {
          ++out.stuck;
          first_stuck = std::min<std::uint64_t>(first_stuck, from);
        }
      }
      send.clear();
      for (int r = 0; r < size; ++r) {
        offsets[static_cast<std::size_t>(r)] = send.size();
        send.insert(send.end(), to[static_cast<std::size_t>(r)].begin(),
                    to[static_cast<std::size_t>(r)].end());
      }
      offsets[static_cast<std::size_t>(size)] = send.size();
      received = ranks.all_to_all(send, offsets);
      std::vector<Word> state(words);
      for (std::size_t at = 0; at + record <= received.size(); at += record) {
        std::memcpy(state.data(), received.data() + at, words * sizeof(Word));
        std::uint64_t k;
        std::memcpy(&k, received.data() + at + words * sizeof(Word), 8);
        if (const auto local = rs.offer(state.data(), k))
          fresh.push_back(*local);
      }
      stop = stop_now();
    }
    if (stop) // a level cut short: its states are not all found
      break;
    level_first += level_size;
    level_size = number_level(rs, fresh, level_first, ranks);
    out.states += level_size;
    ++out.depth;
    stop = level_done(fresh);
  }
  out.edges = ranks.sum(out.edges);
  out.ended = ranks.sum(out.ended);
  out.stuck = ranks.sum(out.stuck);
  if (const std::uint64_t first = ranks.min(first_stuck); first != no_id) {
    out.first_stuck = first;
    out.to_first_stuck = path_to(rs, first, ranks);
  }
  if (stop && *stop != StopReason::found && *stop != StopReason::state_limit)
    out.states = ranks.sum(rs.store.size()); // a level cut short: what each rank holds
  if (out.found) {
    out.states = *out.found + 1; // a sequential search stops at the target
    out.to_found = path_to(rs, *out.found, ranks);
  }
  limits.spend_states(out.states); // (every rank: each holds the property's budget)
  if (out.depth == 0)              // stopped in level 0: the start states it has
    out.start_states = out.states;
  if (stop)
    out.stop = *stop;
  out.peak_rank_bytes = ranks.max(std::max<std::uint64_t>(peak, resident_bytes()));
  out.seconds = ranks.max(static_cast<std::uint64_t>(elapsed() * 1e6)) / 1e6;
  return out;
}

} // namespace checker
