#include "checker/state_tree.hpp"

#include <algorithm>
#include <stdexcept>

namespace checker {

namespace {
// Ids below this are values; from it on, the top bit marks a place in a table.
constexpr std::uint64_t in_table = std::uint64_t{1} << 31;
} // namespace

StateTree::StateTree(std::uint32_t words) : words_(words) {
  if (words < 2)
    throw std::invalid_argument("a state tree needs states of two words or more");
  nodes_.reserve(2 * std::size_t{words});
  build(0, words);
  nodes_.back().table = no_table; // the root's pair is the key
  for (Node& n : nodes_)
    if (&n != &nodes_.back()) {
      n.table = static_cast<std::uint32_t>(tables_.size());
      tables_.push_back(std::make_unique<StateStore>(1));
    }
}

std::uint32_t StateTree::build(std::uint32_t lo, std::uint32_t hi) {
  Node n{lo, hi, 0, 0, 0};
  if (hi - lo > 1) {
    const std::uint32_t mid = lo + (hi - lo + 1) / 2;
    n.left = build(lo, mid);
    n.right = build(mid, hi);
  }
  nodes_.push_back(n);
  return static_cast<std::uint32_t>(nodes_.size() - 1);
}

std::optional<std::uint32_t> StateTree::put(const Node& n, Word value) {
  if (value < in_table)
    return static_cast<std::uint32_t>(value);
  StateStore& table = *tables_[n.table];
  StateStore::IdBlock one;
  const StateStore::Claim claim =
      table.find_or_insert(&value, hash_state(&value, 1), one, [](StateId, std::uint32_t) {});
  if (claim.kind == StateStore::Claim::Kind::full)
    return std::nullopt;
  if (claim.id >= in_table)
    throw std::length_error("compressed store: a part of the state takes more than 2^31 "
                            "values (use the exact store)");
  return static_cast<std::uint32_t>(in_table | claim.id);
}

std::optional<std::uint32_t> StateTree::look_up(const Node& n, Word value) const {
  if (value < in_table)
    return static_cast<std::uint32_t>(value);
  const std::optional<StateId> id = tables_[n.table]->find(&value, hash_state(&value, 1));
  if (!id)
    return std::nullopt;
  return static_cast<std::uint32_t>(in_table | *id);
}

Word StateTree::value_of(const Node& n, std::uint32_t id) const {
  if (id < in_table)
    return id;
  return tables_[n.table]->state(static_cast<StateId>(id & (in_table - 1)))[0];
}

// Children come before their parent in nodes_, so one pass computes every id.
std::optional<Word> StateTree::insert(const Word* state, std::uint32_t* ids) {
  for (std::size_t i = 0; i + 1 < nodes_.size(); ++i) {
    const std::optional<std::uint32_t> id = put(nodes_[i], node_value(i, state, ids));
    if (!id)
      return std::nullopt;
    ids[i] = *id;
  }
  return root_key(ids);
}

std::optional<Word> StateTree::insert_near(const Word* state, const Word* near,
                                           const std::uint32_t* near_ids, std::uint32_t* ids) {
  for (std::size_t i = 0; i + 1 < nodes_.size(); ++i) {
    const Node& n = nodes_[i];
    const bool same = n.hi - n.lo == 1
                          ? state[n.lo] == near[n.lo]
                          : ids[n.left] == near_ids[n.left] && ids[n.right] == near_ids[n.right];
    if (same) {
      ids[i] = near_ids[i];
      continue;
    }
    const std::optional<std::uint32_t> id = put(n, node_value(i, state, ids));
    if (!id)
      return std::nullopt;
    ids[i] = *id;
  }
  return root_key(ids);
}

std::optional<Word> StateTree::find(const Word* state, std::uint32_t* ids) const {
  for (std::size_t i = 0; i + 1 < nodes_.size(); ++i) {
    const std::optional<std::uint32_t> id = look_up(nodes_[i], node_value(i, state, ids));
    if (!id)
      return std::nullopt;
    ids[i] = *id;
  }
  return root_key(ids);
}

void StateTree::decode(Word key, Word* out, std::uint32_t* ids) const {
  // Down from the root, a node and its value at a time (the tree is at most 33 deep).
  struct Pending {
    std::uint32_t node;
    Word value;
  };
  Pending stack[80];
  std::size_t depth = 0;
  stack[depth++] = {static_cast<std::uint32_t>(nodes_.size() - 1), key};
  while (depth > 0) {
    const Pending p = stack[--depth];
    const Node& n = nodes_[p.node];
    if (n.hi - n.lo == 1) {
      out[n.lo] = p.value;
      continue;
    }
    const auto left = static_cast<std::uint32_t>(p.value >> 32);
    const auto right = static_cast<std::uint32_t>(p.value);
    if (ids) {
      ids[n.left] = left;
      ids[n.right] = right;
    }
    stack[depth++] = {n.right, value_of(nodes_[n.right], right)};
    stack[depth++] = {n.left, value_of(nodes_[n.left], left)};
  }
}

void StateTree::set_inserters(std::uint32_t inserters) {
  for (auto& table : tables_)
    table->set_inserters(inserters);
}

std::uint64_t StateTree::more_for(const StateStore& table) {
  return std::max<std::uint64_t>(table.size() / 4, 1024);
}

// Grown a little before it is full, so that the workers seldom stop for it.
bool StateTree::table_needs_room(const StateStore& table) const {
  return table.size() + table.size() / 32 + 64 >= table.room();
}

bool StateTree::needs_room() const {
  return std::any_of(tables_.begin(), tables_.end(),
                     [&](const auto& table) { return table_needs_room(*table); });
}

std::size_t StateTree::room_bytes() const {
  std::size_t bytes = 0;
  for (const auto& table : tables_)
    if (table_needs_room(*table))
      bytes += table->room_bytes(more_for(*table));
  return bytes;
}

void StateTree::make_room() {
  for (auto& table : tables_)
    if (table_needs_room(*table))
      table->make_room(more_for(*table));
}

std::size_t StateTree::memory_bytes() const {
  std::size_t bytes = 0;
  for (const auto& table : tables_)
    bytes += table->memory_bytes();
  return bytes;
}

std::uint64_t StateTree::parts() const {
  std::uint64_t parts = 0;
  for (const auto& table : tables_)
    parts += table->size();
  return parts;
}

} // namespace checker
