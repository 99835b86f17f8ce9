#pragma once
// The compressed store's tables (ExploreOptions::store = StoreKind::compressed): tree
// compression, as LTSmin's tree database has it. A state of W words is the root of a
// balanced binary tree over its words. Each word (a leaf) and each pair of sibling parts
// (an inner node) has a 32-bit id; the root's pair of ids is the state's one-word key,
// which the explorer's StateStore holds in place of the state. Each position of the tree
// has a table of the values met there (a StateStore of one-word "states"), so a part that
// many states share (an empty queue, a robot's variables that other robots' steps leave
// alone) is held once.
//
// An id below 2^31 is the part's value itself (a small word, or the pair of two such ids:
// empty places cost nothing); a value of 2^31 or more is put in its position's table and
// its id there, with the top bit set, is the part's id. So an id names exactly one value
// of its position, and a key exactly one state: the store stays exact.
//
// Threads put parts concurrently (insert()), each position's table as the explorer's store
// (state_store.hpp). A table never grows on its own: insert() says so when one is out of
// room, and make_room() is then called while nobody uses the tables (the explorer's growth
// gate). A part put for a state that the run then does not keep (a limit met) stays, and
// costs only its place.

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "checker/state_store.hpp"

namespace checker {

class StateTree {
public:
  // `words` >= 2 (a one-word state is its own key).
  explicit StateTree(std::uint32_t words);

  std::uint32_t words() const { return words_; }
  // The scratch words insert() and find() need (one id per node).
  std::size_t scratch_size() const { return nodes_.size(); }

  // The key of `state`, its parts put where they are new; nullopt when a table is out of
  // room (make_room() first). Safe with other threads doing the same. `ids` (scratch_size()
  // words) receives the id of each node.
  std::optional<Word> insert(const Word* state, std::uint32_t* ids);
  // insert() for a state that differs from `near` (whose nodes have the ids `near_ids`, as
  // decode() gives them) in a few words: the nodes over unchanged words keep their ids
  // without a lookup.
  std::optional<Word> insert_near(const Word* state, const Word* near,
                                  const std::uint32_t* near_ids, std::uint32_t* ids);
  // The key of `state` when all its parts are held (else the state was never put).
  std::optional<Word> find(const Word* state, std::uint32_t* ids) const;
  // The state whose key is `key` (words() words into `out`); with `ids`, the id of each
  // node but the root.
  void decode(Word key, Word* out, std::uint32_t* ids = nullptr) const;

  // How many threads insert at once (each table leaves them room).
  void set_inserters(std::uint32_t inserters);
  // Whether some table is out of room or close to it (make_room() would grow it).
  bool needs_room() const;
  // What make_room() would add, in bytes.
  std::size_t room_bytes() const;
  // Grows the tables that need it; while nobody uses them.
  void make_room();

  // The tables' memory (as StateStore counts it).
  std::size_t memory_bytes() const;
  // The parts held in all the tables.
  std::uint64_t parts() const;

private:
  static constexpr std::uint32_t no_table = 0xffffffffu;
  // A node of the tree over words [lo, hi): a leaf when hi = lo + 1, else the pair of its
  // children (indices into nodes_, which lists children before their parent: the root is
  // last).
  struct Node {
    std::uint32_t lo, hi;
    std::uint32_t left, right;
    std::uint32_t table; // no_table for the root
  };
  std::uint32_t build(std::uint32_t lo, std::uint32_t hi);
  // The value of node `i` of `state`, its children's ids being in `ids`.
  Word node_value(std::size_t i, const Word* state, const std::uint32_t* ids) const {
    const Node& n = nodes_[i];
    return n.hi - n.lo == 1 ? state[n.lo] : (Word{ids[n.left]} << 32) | ids[n.right];
  }
  Word root_key(const std::uint32_t* ids) const {
    const Node& root = nodes_.back();
    return (Word{ids[root.left]} << 32) | ids[root.right];
  }
  // The id of a part whose value is `value` at node `n`, or nullopt (insert: out of room;
  // find: not held).
  std::optional<std::uint32_t> put(const Node& n, Word value);
  std::optional<std::uint32_t> look_up(const Node& n, Word value) const;
  Word value_of(const Node& n, std::uint32_t id) const;
  // How many more parts a table gets room for at make_room().
  static std::uint64_t more_for(const StateStore& table);
  bool table_needs_room(const StateStore& table) const;

  std::uint32_t words_;
  std::vector<Node> nodes_;
  std::vector<std::unique_ptr<StateStore>> tables_;
};

} // namespace checker
