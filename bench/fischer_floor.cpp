// Fischer's protocol explored by hand-written code: no DSL, no checker, only the
// breadth-first search and a hash table. It measures what the search costs on this
// machine when generating successors is nearly free, so that tioa-check's time on the
// same instance can be split into the store's share and the rest (bench/README.md,
// "A hand-written floor"). Its counts are an independent check of the `fischer` model's
// (tests/catalogue/fischer_test.cpp, ../shared/peers/README.md).
//
//   build/bench/fischer_floor N [plain|ids]
//
// Semantics: ../shared/peers/models/fischer_N*_1p.pml with A = 1, B = 2 (the peers'
// defaults): per process a location and a clock in 0..3 (saturating), a shared id; a tick
// is enabled when no process is in REQ with c >= A and advances the clocks of REQ and WAIT.
//
// Tables:
//  - plain: 8-byte slots holding the state itself (+1, so that 0 is empty), 2^25 slots
//    allocated once: one cache miss decides a lookup, and the table never grows.
//  - ids:   tioa-check's design (checker/state_store.hpp): 32-bit slots holding a tag and
//    an id, the states in an arena in id order, a parent id per state, a table that
//    starts small and is built again twice as big at three quarters full.
// Both prefetch the slots of a batch of successors before looking any of them up.

#include <sys/mman.h>

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <type_traits>
#include <vector>

namespace {

using State = std::uint64_t; // id: 4 bits, then loc[p] 2 bits each, then c[p] 2 bits each

constexpr int a_bound = 1, b_bound = 2, clock_cap = 3;
enum Loc : unsigned { idle = 0, req = 1, wait = 2, cs = 3 };

struct Layout {
  int n;
  unsigned loc(State s, int p) const { return (s >> (4 + 2 * p)) & 3; }
  unsigned clock(State s, int p) const { return (s >> (4 + 2 * n + 2 * p)) & 3; }
  static unsigned id(State s) { return s & 15; }
  State with_loc(State s, int p, unsigned v) const {
    const int at = 4 + 2 * p;
    return (s & ~(State{3} << at)) | (State{v} << at);
  }
  State with_clock(State s, int p, unsigned v) const {
    const int at = 4 + 2 * n + 2 * p;
    return (s & ~(State{3} << at)) | (State{v} << at);
  }
  static State with_id(State s, unsigned v) { return (s & ~State{15}) | v; }
};

std::uint64_t hash(State s) { // a 64-bit finaliser (MurmurHash3's)
  s ^= s >> 33;
  s *= 0xff51afd7ed558ccdULL;
  s ^= s >> 33;
  s *= 0xc4ceb9fe1a85ec53ULL;
  return s ^ (s >> 33);
}

template <class T> T* map_array(std::size_t count) {
  void* p =
      mmap(nullptr, count * sizeof(T), PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (p == MAP_FAILED) {
    std::fprintf(stderr, "fischer_floor: out of memory\n");
    std::exit(2);
  }
  madvise(p, count * sizeof(T), MADV_HUGEPAGE);
  return static_cast<T*>(p);
}

// 8-byte slots holding the state; allocated once.
class PlainTable {
public:
  PlainTable() : slots_(map_array<State>(std::size_t{1} << bits)) {}
  void prefetch(std::uint64_t h) const { __builtin_prefetch(slots_ + (h & mask)); }
  void prefetch_state(std::uint64_t) const {}
  bool insert(State s, std::uint64_t h) { // true when new
    for (std::size_t i = h & mask;; i = (i + 1) & mask) {
      if (slots_[i] == 0) {
        if (++size_ > (mask + 1) / 4 * 3) {
          std::fprintf(stderr, "fischer_floor: the plain table is full\n");
          std::exit(2);
        }
        slots_[i] = s + 1;
        return true;
      }
      if (slots_[i] == s + 1)
        return false;
    }
  }
  std::size_t bytes() const { return (mask + 1) * sizeof(State); }

private:
  static constexpr int bits = 25;
  static constexpr std::size_t mask = (std::size_t{1} << bits) - 1;
  State* slots_;
  std::size_t size_ = 0;
};

// tioa-check's layout: tag | id + 1 in 32 bits, states in an arena, a parent per state.
class IdTable {
public:
  IdTable() : arena_(map_array<State>(arena_cap)) { build(10); }
  void prefetch(std::uint64_t h) const { __builtin_prefetch(slots_ + (h & mask_)); }
  void prefetch_state(std::uint64_t h) const {
    const std::uint32_t slot = slots_[h & mask_];
    if (slot != 0 && slot >> bits_ == tag(h))
      __builtin_prefetch(arena_ + (slot & mask_) - 1);
  }
  bool insert(State s, std::uint64_t h, std::uint32_t parent) {
    for (std::size_t i = h & mask_;; i = (i + 1) & mask_) {
      const std::uint32_t slot = slots_[i];
      if (slot == 0) {
        if (size_ + 1 > (mask_ + 1) / 4 * 3) {
          build(bits_ + 1);
          return insert(s, h, parent);
        }
        if (size_ == arena_cap) {
          std::fprintf(stderr, "fischer_floor: the arena is full\n");
          std::exit(2);
        }
        arena_[size_] = s;
        parents_.push_back(parent);
        slots_[i] = (tag(h) << bits_) | static_cast<std::uint32_t>(++size_);
        return true;
      }
      if (slot >> bits_ == tag(h) && arena_[(slot & mask_) - 1] == s)
        return false;
    }
  }
  std::size_t bytes() const {
    return (mask_ + 1) * sizeof(std::uint32_t) + size_ * (sizeof(State) + sizeof(std::uint32_t));
  }

private:
  static constexpr std::size_t arena_cap = std::size_t{1} << 27;
  std::uint32_t tag(std::uint64_t h) const { return static_cast<std::uint32_t>(h >> (32 + bits_)); }
  void build(int bits) { // the old table first given back, the new one filled from the arena
    if (slots_)
      munmap(slots_, (mask_ + 1) * sizeof(std::uint32_t));
    bits_ = bits;
    mask_ = (std::size_t{1} << bits) - 1;
    slots_ = map_array<std::uint32_t>(mask_ + 1);
    for (std::size_t id = 0; id < size_; ++id) {
      const std::uint64_t h = hash(arena_[id]);
      std::size_t i = h & mask_;
      while (slots_[i] != 0)
        i = (i + 1) & mask_;
      slots_[i] = (tag(h) << bits_) | static_cast<std::uint32_t>(id + 1);
    }
  }
  int bits_ = 0;
  std::size_t mask_ = 0;
  std::uint32_t* slots_ = nullptr;
  State* arena_;
  std::vector<std::uint32_t> parents_;
  std::size_t size_ = 0;
};

struct Counts {
  std::size_t states = 0, edges = 0, depth = 0, table_bytes = 0;
};

template <class Table> Counts explore(const Layout& f) {
  Table table;
  Counts counts;
  std::vector<State> frontier{0}, next;
  std::vector<std::uint32_t> frontier_ids{0}, next_ids;
  constexpr std::size_t batch = 64;
  State pending[batch + 16];
  std::uint64_t hashes[batch + 16];
  std::uint32_t parents[batch + 16];
  std::size_t count = 0;
  auto insert = [&](State s, std::uint64_t h, std::uint32_t parent) {
    bool fresh;
    if constexpr (std::is_same_v<Table, IdTable>)
      fresh = table.insert(s, h, parent);
    else
      fresh = table.insert(s, h);
    if (fresh) {
      next.push_back(s);
      next_ids.push_back(static_cast<std::uint32_t>(counts.states++));
    }
  };
  insert(0, hash(0), 0);
  frontier.swap(next);
  frontier_ids.swap(next_ids);
  auto flush = [&] {
    for (std::size_t k = 0; k < count; ++k)
      table.prefetch_state(hashes[k]);
    for (std::size_t k = 0; k < count; ++k)
      insert(pending[k], hashes[k], parents[k]);
    count = 0;
  };
  while (!frontier.empty()) {
    next.clear();
    next_ids.clear();
    for (std::size_t k = 0; k < frontier.size(); ++k) {
      const State s = frontier[k];
      auto emit = [&](State t) {
        ++counts.edges;
        hashes[count] = hash(t);
        table.prefetch(hashes[count]);
        pending[count] = t;
        parents[count++] = frontier_ids[k];
      };
      bool urgent = false;
      const unsigned id = Layout::id(s);
      for (int p = 0; p < f.n; ++p) {
        const unsigned l = f.loc(s, p), c = f.clock(s, p), self = static_cast<unsigned>(p + 1);
        if (l == idle && id == 0)
          emit(f.with_clock(f.with_loc(s, p, req), p, 0));
        if (l == req) {
          emit(f.with_clock(Layout::with_id(f.with_loc(s, p, wait), self), p, 0));
          urgent = urgent || c >= a_bound;
        }
        if (l == wait && c >= b_bound)
          emit(f.with_clock(f.with_loc(s, p, id == self ? cs : idle), p, 0));
        if (l == cs)
          emit(Layout::with_id(f.with_loc(s, p, idle), 0));
      }
      if (!urgent) {
        State t = s;
        for (int p = 0; p < f.n; ++p) {
          const unsigned l = f.loc(s, p), c = f.clock(s, p);
          if ((l == req || l == wait) && c < clock_cap)
            t = f.with_clock(t, p, c + 1);
        }
        emit(t);
      }
      if (count >= batch)
        flush();
    }
    flush();
    frontier.swap(next);
    frontier_ids.swap(next_ids);
    if (!frontier.empty())
      ++counts.depth;
  }
  counts.table_bytes = table.bytes();
  return counts;
}

} // namespace

int main(int argc, char** argv) {
  const int n = argc > 1 ? std::atoi(argv[1]) : 9;
  const std::string table = argc > 2 ? argv[2] : "ids";
  if (n < 1 || n > 15 || (table != "plain" && table != "ids")) {
    std::fprintf(stderr, "usage: fischer_floor N (1..15) [plain|ids]\n");
    return 2;
  }
  const auto start = std::chrono::steady_clock::now();
  const Counts c = table == "plain" ? explore<PlainTable>({n}) : explore<IdTable>({n});
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf(
      "fischer N=%d (%s table): %zu states, %zu edges, %zu levels after the start, %.2f s, %.1f "
      "Mstates/s, %.1f bytes/state in the store\n",
      n, table.c_str(), c.states, c.edges, c.depth, seconds, c.states / seconds / 1e6,
      double(c.table_bytes) / double(c.states));
  return 0;
}
