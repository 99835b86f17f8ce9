#include "checker/distributed_explorer.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstring>
#include <exception>
#include <mutex>
#include <new>
#include <stdexcept>
#include <string>

#include "checker/fingerprint.hpp"
#include "checker/interrupt.hpp"
#include "checker/mapped_memory.hpp"
#include "checker/memory_budget.hpp"
#include "checker/parallel_for.hpp"
#include "checker/state_store.hpp"
#include "checker/trace.hpp"
#include "tioa/errors.hpp"

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
constexpr std::uint64_t no_key = ~std::uint64_t{0};

// Frontier states a thread of a rank expands before an exchange: bounds what a round sends.
constexpr std::size_t round_states = 1 << 14;
// Start states every rank enumerates between two looks at the limits.
constexpr std::uint64_t start_round = 1 << 16;
// Received states a thread hashes and prefetches before it inserts them.
constexpr std::size_t insert_batch = 16;

// parallel_for for bodies that may throw (a model's error in a guard): the first exception
// is thrown again once every thread has stopped.
template <class Body> void on_threads(std::uint32_t threads, std::uint64_t n, Body&& body) {
  std::exception_ptr error;
  std::mutex first;
  parallel_for(
      threads, n,
      [&](std::uint64_t begin, std::uint64_t end) {
        try {
          body(begin, end);
        } catch (...) {
          const std::lock_guard<std::mutex> lock(first);
          if (!error)
            error = std::current_exception();
        }
      },
      1);
  if (error)
    std::rethrow_exception(error);
}

// One rank's states. Local ids are dense and in the order of insertion, so a level's new
// states are the local ids from `level_begin` on. Per state, 12 bytes beside the store:
// its id in the whole run, the id of its parent (no_id for a start state), and `by_id`,
// the local ids in order of id (ids increase along it) for the trace. The level being
// built also has each new state's smallest discovery key so far.
//
// On the fingerprint store (fingerprint.hpp) the store holds each state's fingerprint,
// and the full states are kept only for the level just numbered (the frontier, from
// `frontier_begin`) and the level being built, as one process keeps them. On the
// compressed store (state_tree.hpp) it holds each state's key into the rank's tree of
// parts, and any state is decoded from it.
struct RankStates {
  RankStates(std::uint32_t words, std::uint32_t threads, StoreKind kind)
      : store(kind == StoreKind::exact || words == 1 ? words : 1), inserters(threads), words(words),
        full_words(kind == StoreKind::fingerprint ? words : 0) {
    store.set_inserters(threads, 1);                  // blocks of one id: no holes
    if (kind == StoreKind::compressed && words > 1) { // (one word is its own key)
      tree = std::make_unique<StateTree>(words);
      tree->set_inserters(threads);
    }
  }
  StateStore store;
  std::unique_ptr<StateTree> tree; // the compressed store's parts
  std::uint32_t inserters;
  std::uint32_t words;      // of a state
  std::uint32_t full_words; // the fingerprint store: a state's words (0: the exact store)
  MappedVector<std::uint32_t> id, parent; // (never held twice as they grow)
  MappedVector<StateId> by_id;
  StateId level_begin = 0;
  std::vector<std::uint64_t> level_key;        // [local - level_begin]
  std::vector<Word> level_full, frontier_full; // the fingerprint store's full states
  StateId frontier_begin = 0;                  // the local id of frontier_full's first

  // A state of the frontier (on the exact and compressed stores, any state), decoded into
  // `buffer` on the compressed store.
  const Word* state(StateId local, std::vector<Word>& buffer) const {
    if (full_words)
      return frontier_full.data() + std::size_t{local - frontier_begin} * full_words;
    return tree ? decoded(local, buffer) : store.state(local);
  }
  // What the store holds for the state `local` as a state: the state, or on the
  // fingerprint store its fingerprint.
  const Word* held(StateId local, std::vector<Word>& buffer) const {
    return tree ? decoded(local, buffer) : store.state(local);
  }
  std::uint32_t held_words() const { return tree ? words : store.words(); }
  // The hash of `state` that decides its owner and, but on the compressed store, its
  // place in the owner's table; and what the store holds for it (the state, or its
  // fingerprint in `key`). On the compressed store the owner makes the key (insert_key).
  const Word* store_key(const Word* state, Word& key, std::uint64_t& hash) const {
    if (!full_words) {
      hash = hash_state(state, words);
      return state;
    }
    key = fingerprint(state, words);
    hash = hash_state(&key, 1);
    return &key;
  }
  // The owner's side: what the store holds for `state`, and its hash in the table. On the
  // compressed store its key, its new parts put in the tree first; null when a table of
  // the tree is full (grow_tree(), then again). Thread-safe; `ids`: the tree's scratch
  // (tree_scratch()).
  const Word* insert_key(const Word* state, Word& key, std::uint64_t& hash, std::uint32_t* ids) {
    if (!tree)
      return store_key(state, key, hash);
    const std::optional<Word> made = tree->insert(state, ids);
    if (!made)
      return nullptr;
    key = *made;
    hash = hash_state(&key, 1);
    return &key;
  }
  // Grows the tables of the tree that are (nearly) full. While no thread uses the tree.
  void grow_tree() { tree->make_room(); }
  std::size_t tree_scratch() const { return tree ? tree->scratch_size() : 0; }

  // Room to insert `more` states, from any number of threads at once.
  void reserve(std::uint64_t more) {
    // (find_or_insert leaves a slack of one id per inserter below id_limit())
    if (store.size() + more + inserters > store.id_limit())
      store.make_room(more);
    level_key.resize(store.size() + more - level_begin, no_key);
    level_full.resize(level_key.size() * full_words);
  }
  // Inserts a state found with `k` (room reserved); a state of the level being built keeps
  // its smallest key. Thread-safe.
  // `full`: the state whose key `state` is (the fingerprint store keeps it for the level).
  void offer(const Word* state, std::uint64_t hash, std::uint64_t k, StateStore::IdBlock& ids,
             const Word* full) {
    const auto claim = store.find_or_insert(state, hash, ids, [&](StateId local, std::uint32_t) {
      if (full_words)
        std::copy(full, full + full_words,
                  level_full.begin() + std::ptrdiff_t(local - level_begin) * full_words);
    });
    if (claim.kind == StateStore::Claim::Kind::full)
      throw std::logic_error("distributed explorer: no room reserved in the store");
    if (claim.id < level_begin)
      return; // a state of an earlier level
    std::atomic_ref<std::uint64_t> key(level_key[claim.id - level_begin]);
    std::uint64_t now = key.load(std::memory_order_relaxed);
    while (k < now && !key.compare_exchange_weak(now, k, std::memory_order_relaxed)) {
    }
  }
  // The level's new states are all inserted: drop the keys reserved for none.
  void close_level() {
    level_key.resize(store.size() - level_begin);
    level_full.resize(level_key.size() * full_words);
  }

private:
  const Word* decoded(StateId local, std::vector<Word>& buffer) const {
    buffer.resize(words);
    tree->decode(store.state(local)[0], buffer.data());
    return buffer.data();
  }
};

// Numbers the level's new states as one process would: by their keys among every rank's;
// `first` is the id of the level's first state. Returns the level's size over all ranks and
// starts the next level.
std::uint64_t number_level(RankStates& rs, std::uint64_t first, Collective& ranks) {
  rs.close_level();
  const auto count = static_cast<StateId>(rs.level_key.size());
  std::vector<StateId> order(count); // the level's states by key (offsets from level_begin)
  for (StateId i = 0; i < count; ++i)
    order[i] = i;
  std::sort(order.begin(), order.end(),
            [&](StateId a, StateId b) { return rs.level_key[a] < rs.level_key[b]; });
  std::vector<std::uint8_t> mine;
  mine.reserve(std::size_t{count} * 8);
  for (StateId i : order)
    append_bytes(mine, &rs.level_key[i], 8);
  std::vector<std::uint64_t> sizes;
  const std::vector<std::uint8_t> all = ranks.all_gather(mine, sizes);
  std::uint64_t total = 0;
  for (std::uint64_t bytes : sizes)
    total += bytes / 8;
  // Each of my keys' place: how many keys of every rank are smaller (keys are unique).
  std::vector<std::uint64_t> place(count, 0);
  std::size_t at = 0;
  for (std::uint64_t bytes : sizes) {
    const std::size_t n = bytes / 8;
    std::size_t j = 0;
    for (StateId i = 0; i < count; ++i) {
      const std::uint64_t k = rs.level_key[order[i]];
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
  rs.id.resize(rs.level_begin + std::size_t{count});
  rs.parent.resize(rs.id.size());
  for (StateId i = 0; i < count; ++i) {
    const StateId local = rs.level_begin + order[i];
    const std::uint64_t k = rs.level_key[order[i]];
    rs.id[local] = static_cast<std::uint32_t>(first + place[i]);
    rs.parent[local] = k & start_key_bit ? no_id : static_cast<std::uint32_t>(k >> 32);
    rs.by_id.push_back(local);
  }
  rs.frontier_begin = rs.level_begin; // the level just numbered is the next frontier
  rs.frontier_full.swap(rs.level_full);
  rs.level_full.clear();
  rs.level_begin += count;
  rs.level_key.clear();
  return total;
}

// The smallest id among this rank's states [begin, end) that is a target (no_id: none).
std::uint64_t first_target(const RankStates& rs, StateId begin, StateId end,
                           const tioa::StatePredicate& target, std::uint32_t threads) {
  std::atomic<std::uint64_t> found{no_id};
  if (target)
    on_threads(threads, end - begin, [&](std::uint64_t from, std::uint64_t to) {
      std::uint64_t mine = no_id;
      std::vector<Word> buffer; // (decoded: the compressed store)
      for (std::uint64_t i = begin + from; i < begin + to; ++i)
        if (rs.id[i] < mine && target(tioa::State(rs.state(static_cast<StateId>(i), buffer), 0)))
          mine = rs.id[i];
      std::uint64_t now = found.load();
      while (mine < now && !found.compare_exchange_weak(now, mine)) {
      }
    });
  return found.load();
}

// The local id of the state `id` when this rank owns it.
std::optional<StateId> local_of(const RankStates& rs, std::uint64_t id) {
  const auto it =
      std::lower_bound(rs.by_id.begin(), rs.by_id.end(), id,
                       [&](StateId local, std::uint64_t wanted) { return rs.id[local] < wanted; });
  if (it != rs.by_id.end() && rs.id[*it] == id)
    return *it;
  return std::nullopt;
}

// What the stores hold for the states from a start state to `id` (the states, or their
// fingerprints), asking the owner of each in turn.
std::vector<std::vector<Word>> path_to(const RankStates& rs, std::uint64_t id, Collective& ranks) {
  const std::uint32_t words = rs.held_words();
  std::vector<std::vector<Word>> path;
  std::vector<Word> buffer;
  for (;;) {
    std::vector<std::uint8_t> mine;
    if (const auto local = local_of(rs, id)) {
      append_bytes(mine, rs.held(*local, buffer), words * sizeof(Word));
      append_bytes(mine, &rs.parent[*local], 4);
    }
    std::vector<std::uint64_t> sizes;
    const std::vector<std::uint8_t> all = ranks.all_gather(mine, sizes);
    if (all.size() != words * sizeof(Word) + 4)
      throw std::logic_error("distributed trace: state " + std::to_string(id) + " has " +
                             std::to_string(all.size()) + " bytes of owners");
    std::vector<Word> state(words);
    std::memcpy(state.data(), all.data(), words * sizeof(Word));
    std::uint32_t parent;
    std::memcpy(&parent, all.data() + words * sizeof(Word), 4);
    path.push_back(std::move(state));
    if (parent == no_id)
      break;
    id = parent;
  }
  std::reverse(path.begin(), path.end());
  return path;
}

// The states from a start state to `id`. On the fingerprint store they are rebuilt by
// re-execution from the fingerprints (trace.hpp), ending at `last`: the state `id`, given
// by the rank that kept it (null on the others).
std::vector<std::vector<Word>> trace_states(const RankStates& rs, std::uint64_t id,
                                            const std::vector<Word>* last,
                                            const tioa::SuccessorGenerator& generator,
                                            const tioa::StartSet& start, Collective& ranks) {
  std::vector<std::vector<Word>> path = path_to(rs, id, ranks);
  if (!rs.full_words)
    return path;
  std::vector<std::uint8_t> mine;
  if (last)
    append_bytes(mine, last->data(), last->size() * sizeof(Word));
  std::vector<std::uint64_t> sizes;
  const std::vector<std::uint8_t> all = ranks.all_gather(mine, sizes);
  std::vector<Word> end(all.size() / sizeof(Word));
  std::memcpy(end.data(), all.data(), end.size() * sizeof(Word));
  std::vector<std::uint64_t> fingerprints;
  for (const std::vector<Word>& held : path)
    fingerprints.push_back(held.front());
  return states_with_fingerprints(generator, start, fingerprints, end);
}

// An error of this rank alone, caught where it happened, so that the rank goes on making
// the collective calls and the others learn of it at the next look at the limits instead
// of waiting for it forever.
struct RankFailure {
  enum Kind : std::uint8_t { none, memory, model, other } kind = none;
  std::string what;

  template <class Work> void guard(Work&& work) {
    if (kind != none)
      return; // nothing more from a rank that failed
    try {
      work();
    } catch (const std::bad_alloc&) {
      kind = memory;
      what = "out of memory";
    } catch (const std::length_error& e) { // the store is full
      kind = memory;
      what = e.what();
    } catch (const tioa::ModelError& e) {
      kind = model;
      what = e.what();
    } catch (const std::exception& e) {
      kind = other;
      what = e.what();
    }
  }
};

// What a thread of a rank gathers while it expands its part of a round.
struct ExpandPart {
  std::vector<std::vector<std::uint8_t>> to; // per owner: successors and their keys
  std::vector<Word> scratch;
  ZeroTimeReduction::Scratch reduction;
  std::vector<Word> decoded; // a frontier state (the compressed store)
  std::uint64_t edges = 0, ended = 0, stuck = 0, first_stuck = no_id;
  std::vector<Word> first_stuck_state;
};

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
                                           const tioa::StatePredicate& ended,
                                           const ZeroTimeReduction* reduction, Collective& ranks) {
  const auto began = std::chrono::steady_clock::now();
  auto elapsed = [&] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
  };
  const Limits& limits = options.limits;
  const std::uint32_t words = generator.words();
  const std::uint32_t threads = std::max(1u, options.threads);
  const int me = ranks.rank(), size = ranks.size();
  DistributedExploration out;
  out.threads = threads;
  // What the property's budget has left (options.hpp): nothing left, nothing explored.
  const std::uint64_t max_states = limits.states_left();
  if (limits.states_exhausted()) {
    out.stop = StopReason::state_limit;
    return out;
  }
  out.fingerprints = options.store == StoreKind::fingerprint;
  out.compressed = options.store == StoreKind::compressed;
  RankStates rs(words, threads, options.store);
  std::size_t peak = 0;
  RankFailure failure;

  // A rank failed (every rank calls this when one did): the first failing rank's error. Out
  // of memory (or a full store), the run stops as at the memory limit, saying which rank;
  // any other error is thrown on every rank, as one process throws it.
  auto failed = [&]() -> StopReason {
    std::vector<std::uint8_t> mine;
    if (failure.kind != RankFailure::none) {
      mine.push_back(failure.kind);
      append_bytes(mine, failure.what.data(), failure.what.size());
    }
    std::vector<std::uint64_t> sizes;
    const std::vector<std::uint8_t> all = ranks.all_gather(mine, sizes);
    int rank = 0;
    while (sizes[static_cast<std::size_t>(rank)] == 0)
      ++rank;
    const auto kind = static_cast<RankFailure::Kind>(all[0]);
    const std::string what(all.begin() + 1,
                           all.begin() +
                               static_cast<std::ptrdiff_t>(sizes[static_cast<std::size_t>(rank)]));
    const std::string where = "rank " + std::to_string(rank) + " of " + std::to_string(size);
    if (kind == RankFailure::model)
      throw tioa::ModelError(what);
    if (kind == RankFailure::other)
      throw std::runtime_error(what + " (" + where + ")");
    out.failure = where + " stopped the run: " + what;
    return StopReason::memory_limit;
  };

  // Between rounds: any rank out of time or memory, failed or asked to stop, stops every
  // rank.
  auto stop_now = [&]() -> std::optional<StopReason> {
    const std::uint64_t resident = resident_bytes();
    peak = std::max<std::size_t>(peak, resident);
    std::uint64_t reason = 0;
    if (failure.kind != RankFailure::none)
      reason = 4;
    else if (interrupted())
      reason = 3;
    else if (resident_over_limit(limits)) // (as one process counts it, per rank)
      reason = 2;
    else if (limits.out_of_time(elapsed()))
      reason = 1;
    switch (ranks.max(reason)) {
    case 4:
      return failed();
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

  // After a level is numbered (the local ids [begin, end)): its first target, or the state
  // limit. A sequential search keeps the first max_states states (ids below it) and goes on
  // with the level for the counts (expansion.hpp), so only a target among those counts.
  // Ids are 32 bits (as in one process's store): a run with more states stops there.
  auto level_done = [&](StateId begin, StateId end) -> std::optional<StopReason> {
    std::uint64_t mine = no_id;
    failure.guard([&] { mine = first_target(rs, begin, end, target, threads); });
    if (ranks.max(failure.kind != RankFailure::none)) // the predicate failed on a rank
      return failed();
    const std::uint64_t found = ranks.min(mine);
    if (found != no_id && (!max_states || found < max_states)) {
      out.found = found;
      return StopReason::found;
    }
    if (max_states && out.states > max_states) {
      out.states = max_states;
      return StopReason::state_limit;
    }
    if (out.states >= StateStore::max_states)
      return StopReason::state_limit;
    return std::nullopt;
  };

  // Level 0: every rank enumerates the start set and keeps the states it owns. Every
  // start_round states enumerated (the same on every rank) the ranks stop together at a
  // target, the state limit or a time or memory limit, as one process stops inserting them
  // (start_insertion.hpp): the states enumerated so far are there, so the ids are right.
  struct StopEnumeration {};
  std::optional<StopReason> stop;
  {
    std::vector<Word> buffer(words + 1, 0);
    std::vector<std::uint32_t> tree_ids(rs.tree_scratch());
    std::uint64_t index = 0, targets = 0;
    StateStore::IdBlock ids;
    auto enough = [&]() -> bool {
      if (ranks.max(failure.kind != RankFailure::none)) {
        stop = failed();
        return true;
      }
      const bool found = ranks.max(targets) > 0;
      if (!found && max_states && ranks.sum(rs.store.size()) > max_states)
        return true;
      if (!found)
        stop = stop_now();
      return found || stop;
    };
    try {
      start.enumerate(buffer.data(), 0, [&] {
        const std::uint64_t i = index++;
        Word key_word;
        std::uint64_t hash;
        rs.store_key(buffer.data(), key_word, hash);
        if (owner_of(hash, size) == me)
          failure.guard([&] {
            const std::uint64_t before = rs.store.size();
            rs.reserve(1);
            const Word* key;
            while (!(key = rs.insert_key(buffer.data(), key_word, hash, tree_ids.data())))
              rs.grow_tree();
            rs.offer(key, hash, start_key_bit | i, ids, buffer.data());
            if (rs.store.size() > before && target && target(tioa::State(buffer.data(), 0)))
              ++targets;
          });
        if (index % start_round == 0 && enough())
          throw StopEnumeration{};
      });
    } catch (const StopEnumeration&) {
    }
    if (!stop && ranks.max(failure.kind != RankFailure::none)) // in the last round
      stop = failed();
  }
  std::uint64_t level_first = 0;
  std::uint64_t level_size = stop ? 0 : number_level(rs, level_first, ranks);
  out.states = out.start_states = level_size;
  if (!stop)
    stop = level_done(0, rs.level_begin);
  if (!stop)
    stop = stop_now();

  const std::size_t record = words * sizeof(Word) + 8;
  std::vector<ExpandPart> parts(threads);
  for (ExpandPart& part : parts) {
    part.to.resize(static_cast<std::size_t>(size));
    part.scratch.assign(words + 1, 0);
  }
  std::vector<std::uint8_t> send;
  std::vector<std::uint64_t> offsets(static_cast<std::size_t>(size) + 1);
  std::vector<StateStore::IdBlock> id_blocks(threads);
  StateId frontier_begin = 0;
  while (level_size > 0 && !stop) {
    const StateId frontier_end = rs.level_begin; // the level just numbered
    const std::uint64_t frontier = frontier_end - frontier_begin;
    const std::uint64_t per_round = round_states * threads;
    const std::uint64_t rounds = ranks.max((frontier + per_round - 1) / per_round);
    for (std::uint64_t round = 0; round < rounds && !stop; ++round) {
      const std::uint64_t begin = std::min(frontier, round * per_round);
      const std::uint64_t end = std::min(frontier, begin + per_round);
      // Expand: each thread its part of the round, into its own messages.
      for (ExpandPart& part : parts)
        for (auto& t : part.to)
          t.clear();
      std::atomic<std::uint32_t> next_part{0};
      failure.guard([&] {
        on_threads(threads, end - begin, [&](std::uint64_t from, std::uint64_t to) {
          ExpandPart& part = parts[next_part.fetch_add(1)];
          for (std::uint64_t f = begin + from; f < begin + to; ++f) {
            const auto s = static_cast<StateId>(frontier_begin + f);
            const std::uint64_t id = rs.id[s];
            std::uint32_t step = 0;
            const auto send = [&](const Word* succ) {
              const std::uint64_t k = step_key(id, step++);
              Word key_word;
              std::uint64_t hash;
              rs.store_key(succ, key_word, hash);
              auto& t = part.to[static_cast<std::size_t>(owner_of(hash, size))];
              append_bytes(t, succ, words * sizeof(Word));
              append_bytes(t, &k, 8);
            };
            const Word* here = rs.state(s, part.decoded);
            // As one process expands it (expansion.hpp): the reduction's successors, or all.
            const std::optional<std::size_t> reduced =
                reduction ? reduction->reduce(here, part.reduction) : std::nullopt;
            std::size_t n = 0;
            if (reduced) {
              n = *reduced;
              for (std::size_t k = 0; k < n; ++k)
                send(part.reduction.successors.data() + k * words);
            } else {
              n = generator.successors(
                  here, part.scratch.data(),
                  [&](const Word* succ, const tioa::StepLabel&) { send(succ); });
            }
            part.edges += n;
            if (n > 0)
              continue;
            if (ended && ended(tioa::State(here, 0))) {
              ++part.ended;
            } else {
              ++part.stuck;
              if (id < part.first_stuck) { // (its state, for a trace on the fingerprint store)
                part.first_stuck = id;
                part.first_stuck_state.assign(here, here + words);
              }
            }
          }
        });
      });
      // Exchange.
      send.clear();
      for (int r = 0; r < size; ++r) {
        offsets[static_cast<std::size_t>(r)] = send.size();
        for (const ExpandPart& part : parts)
          send.insert(send.end(), part.to[static_cast<std::size_t>(r)].begin(),
                      part.to[static_cast<std::size_t>(r)].end());
      }
      offsets[static_cast<std::size_t>(size)] = send.size();
      const std::vector<std::uint8_t> received = ranks.all_to_all(send, offsets);
      // Insert what this rank owns, on every thread.
      const std::size_t count = received.size() / record;
      std::atomic<std::uint32_t> next_block{0};
      // The compressed store: the states whose key found a table of the tree full, inserted
      // after the tables grow (the order of insertion does not change the ids, which the
      // discovery keys give).
      std::vector<std::vector<std::uint64_t>> deferred(threads);
      failure.guard([&] {
        rs.reserve(count);
        on_threads(threads, count, [&](std::uint64_t from, std::uint64_t to) {
          const std::uint32_t block = next_block.fetch_add(1);
          StateStore::IdBlock& ids = id_blocks[block];
          std::vector<std::uint32_t> tree_ids(rs.tree_scratch());
          std::uint64_t hashes[insert_batch];
          Word key_words[insert_batch];
          const Word* keys[insert_batch];
          for (std::uint64_t at = from; at < to; at += insert_batch) {
            const std::uint64_t n = std::min<std::uint64_t>(insert_batch, to - at);
            for (std::uint64_t i = 0; i < n; ++i) {
              const auto* state =
                  reinterpret_cast<const Word*>(received.data() + (at + i) * record);
              keys[i] = rs.insert_key(state, key_words[i], hashes[i], tree_ids.data());
              if (keys[i])
                rs.store.prefetch(hashes[i]);
              else
                deferred[block].push_back(at + i);
            }
            for (std::uint64_t i = 0; i < n; ++i) {
              if (!keys[i])
                continue;
              const std::uint8_t* r = received.data() + (at + i) * record;
              std::uint64_t k;
              std::memcpy(&k, r + words * sizeof(Word), 8);
              rs.offer(keys[i], hashes[i], k, ids, reinterpret_cast<const Word*>(r));
            }
          }
        });
        std::vector<std::uint32_t> tree_ids(rs.tree_scratch());
        for (const std::vector<std::uint64_t>& some : deferred)
          for (const std::uint64_t at : some) {
            const std::uint8_t* r = received.data() + at * record;
            const auto* state = reinterpret_cast<const Word*>(r);
            Word key_word;
            std::uint64_t hash, k;
            const Word* key;
            while (!(key = rs.insert_key(state, key_word, hash, tree_ids.data())))
              rs.grow_tree();
            std::memcpy(&k, r + words * sizeof(Word), 8);
            rs.offer(key, hash, k, id_blocks[0], state);
          }
      });
      stop = stop_now();
    }
    if (stop) // a level cut short: its states are not all found
      break;
    frontier_begin = frontier_end;
    level_first += level_size;
    level_size = number_level(rs, level_first, ranks);
    out.states += level_size;
    ++out.depth;
    stop = level_done(frontier_end, rs.level_begin);
  }
  std::uint64_t first_stuck = no_id;
  const std::vector<Word>* first_stuck_state = nullptr;
  for (const ExpandPart& part : parts) {
    out.reduced_states += part.reduction.reduced;
    out.edges += part.edges;
    out.ended += part.ended;
    out.stuck += part.stuck;
    if (part.first_stuck < first_stuck) {
      first_stuck = part.first_stuck;
      first_stuck_state = &part.first_stuck_state;
    }
  }
  out.edges = ranks.sum(out.edges);
  out.ended = ranks.sum(out.ended);
  out.stuck = ranks.sum(out.stuck);
  out.reduced_states = ranks.sum(out.reduced_states);
  if (const std::uint64_t first = ranks.min(first_stuck); first != no_id) {
    out.first_stuck = first;
    out.to_first_stuck = trace_states(rs, first, first == first_stuck ? first_stuck_state : nullptr,
                                      generator, start, ranks);
  }
  if (stop && *stop != StopReason::found && *stop != StopReason::state_limit)
    out.states = ranks.sum(rs.store.size()); // a level cut short: what each rank holds
  if (out.found) {
    out.states = *out.found + 1; // a sequential search stops at the target
    const std::vector<Word>* found_state = nullptr;
    std::vector<Word> mine, buffer;
    if (const auto local = local_of(rs, *out.found)) {
      const Word* state = rs.state(*local, buffer); // (the frontier's)
      mine.assign(state, state + words);
      found_state = &mine;
    }
    out.to_found = trace_states(rs, *out.found, found_state, generator, start, ranks);
  }
  limits.spend_states(out.states); // (every rank: each holds the property's budget)
  if (out.depth == 0)              // stopped in level 0: the start states it has
    out.start_states = out.states;
  if (stop)
    out.stop = *stop;
  out.peak_rank_bytes = ranks.max(std::max<std::uint64_t>(peak, resident_bytes()));
  if (rs.tree) {
    out.parts = ranks.sum(rs.tree->parts());
    out.store_bytes = ranks.sum(rs.store.memory_bytes() + rs.tree->memory_bytes());
  }
  out.seconds = ranks.max(static_cast<std::uint64_t>(elapsed() * 1e6)) / 1e6;
  return out;
}

} // namespace checker
