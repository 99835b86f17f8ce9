#include "checker/state_expression.hpp"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <memory>
#include <string_view>
#include <unordered_map>
#include <utility>
#include <vector>

#include "tioa/state.hpp"

namespace checker {

namespace {

// ---- the program: a tree of nodes in one vector, evaluated on a state

// `undefined` is the result of a division by zero or an overflow: every comparison with it
// is false.
enum class Status : std::uint8_t { known, bottom, undefined };

struct Value {
  std::int64_t number = 0;
  Status status = Status::known;
};

enum class Op : std::uint8_t {
  constant,
  variable,
  negate,
  add,
  subtract,
  multiply,
  divide,
  remainder,
  count, // how many children hold
  equal,
  not_equal,
  less,
  less_equal,
  greater,
  greater_equal,
  contains,
  logical_not,
  all, // every child holds ('and')
  any, // some child holds ('or')
};

struct Node {
  Op op = Op::constant;
  std::uint32_t first = 0; // the children are Program::children[first, first + count)
  std::uint32_t count = 0;
  Value constant;            // Op::constant
  tioa::Slot slot;           // Op::variable
  std::uint32_t element = 0; // Op::contains: the element's bit
};

struct Program {
  std::vector<Node> nodes;
  std::vector<std::uint32_t> children;
  std::uint32_t root = 0;
};

bool holds(Value v) {
  return v.status == Status::known && v.number != 0;
}
Value truth(bool b) {
  return {b ? 1 : 0, Status::known};
}

Value arithmetic(Op op, Value a, Value b) {
  if (a.status == Status::undefined || b.status == Status::undefined)
    return {0, Status::undefined};
  if (a.status == Status::bottom || b.status == Status::bottom)
    return {0, Status::bottom};
  std::int64_t r = 0;
  bool overflow = false;
  switch (op) {
  case Op::add:
    overflow = __builtin_add_overflow(a.number, b.number, &r);
    break;
  case Op::subtract:
    overflow = __builtin_sub_overflow(a.number, b.number, &r);
    break;
  case Op::multiply:
    overflow = __builtin_mul_overflow(a.number, b.number, &r);
    break;
  default: // divide, remainder
    overflow =
        b.number == 0 || (a.number == std::numeric_limits<std::int64_t>::min() && b.number == -1);
    if (!overflow)
      r = op == Op::divide ? a.number / b.number : a.number % b.number;
    break;
  }
  return overflow ? Value{0, Status::undefined} : Value{r, Status::known};
}

bool compare(Op op, Value a, Value b) {
  if (a.status == Status::undefined || b.status == Status::undefined)
    return false;
  const bool same = a.status == b.status && (a.status == Status::bottom || a.number == b.number);
  if (op == Op::equal)
    return same;
  if (op == Op::not_equal)
    return !same;
  if (a.status == Status::bottom || b.status == Status::bottom)
    return false;
  switch (op) {
  case Op::less:
    return a.number < b.number;
  case Op::less_equal:
    return a.number <= b.number;
  case Op::greater:
    return a.number > b.number;
  default:
    return a.number >= b.number;
  }
}

Value evaluate(const Program& p, std::uint32_t id, const tioa::State& s) {
  const Node& n = p.nodes[id];
  const std::uint32_t* c = p.children.data() + n.first;
  switch (n.op) {
  case Op::constant:
    return n.constant;
  case Op::variable: {
    const std::uint64_t code = s.code(n.slot);
    if (n.slot.has_bottom && code == n.slot.value_codes)
      return {0, Status::bottom};
    return {n.slot.lo + static_cast<std::int64_t>(code), Status::known};
  }
  case Op::negate:
    return arithmetic(Op::subtract, Value{}, evaluate(p, c[0], s));
  case Op::add:
  case Op::subtract:
  case Op::multiply:
  case Op::divide:
  case Op::remainder:
    return arithmetic(n.op, evaluate(p, c[0], s), evaluate(p, c[1], s));
  case Op::count: {
    std::int64_t k = 0;
    for (std::uint32_t i = 0; i < n.count; ++i)
      k += holds(evaluate(p, c[i], s)) ? 1 : 0;
    return {k, Status::known};
  }
  case Op::contains: {
    const Value set = evaluate(p, c[0], s);
    return truth(set.status == Status::known &&
                 (static_cast<std::uint64_t>(set.number) >> n.element & 1) != 0);
  }
  case Op::logical_not:
    return truth(!holds(evaluate(p, c[0], s)));
  case Op::all:
    for (std::uint32_t i = 0; i < n.count; ++i)
      if (!holds(evaluate(p, c[i], s)))
        return truth(false);
    return truth(true);
  case Op::any:
    for (std::uint32_t i = 0; i < n.count; ++i)
      if (holds(evaluate(p, c[i], s)))
        return truth(true);
    return truth(false);
  default: // the comparisons
    return truth(compare(n.op, evaluate(p, c[0], s), evaluate(p, c[1], s)));
  }
}

// ---- names as they are written

const char* const keywords[] = {"and",   "or",  "not", "true", "false",   "bottom",
                                "count", "all", "any", "in",   "contains"};

bool is_keyword(std::string_view word) {
  return std::find(std::begin(keywords), std::end(keywords), word) != std::end(keywords);
}

bool word_start(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_';
}
bool word_char(char c) {
  return word_start(c) || (c >= '0' && c <= '9');
}
bool digit(char c) {
  return c >= '0' && c <= '9';
}

// The length of the name (word, then '.'-joined parts) at the start of `text`; 0 if none.
std::size_t name_length(std::string_view text) {
  if (text.empty() || !word_start(text[0]))
    return 0;
  std::size_t i = 1;
  while (i < text.size()) {
    if (word_char(text[i]))
      ++i;
    else if (text[i] == '.' && i + 1 < text.size() && word_char(text[i + 1]))
      i += 2;
    else
      break;
  }
  return i;
}

bool is_plain_value(std::string_view value) {
  const std::size_t n = name_length(value);
  return n == value.size() && n > 0 && value.find('.') == std::string_view::npos &&
         !is_keyword(value);
}

std::string quoted(std::string_view text, char quote) {
  std::string out(1, quote);
  for (char c : text) {
    out += c;
    if (c == quote)
      out += quote;
  }
  return out + quote;
}

// How a variable is written in an expression: as is when it parses back to itself
// (`loc[1]`, `net.OK[1][2]`), else between backquotes.
std::string written_variable(std::string_view name) {
  const std::size_t base = name_length(name);
  bool plain = base > 0 && !is_keyword(name.substr(0, base));
  for (std::size_t i = base; plain && i < name.size();) {
    const std::size_t close = name.find(']', i);
    if (name[i] != '[' || close == std::string_view::npos) {
      plain = false;
      break;
    }
    const std::string_view index = name.substr(i + 1, close - i - 1);
    const bool negative = !index.empty() && index[0] == '-';
    const std::string_view digits = index.substr(negative ? 1 : 0);
    plain = !digits.empty() && digits.size() <= 18 &&
            std::all_of(digits.begin(), digits.end(), digit) &&
            (digits[0] != '0' || digits.size() == 1) && !(negative && digits == "0");
    i = close + 1;
  }
  return plain ? std::string(name) : quoted(name, '`');
}

std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j)
    row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      const auto lower = [](char c) { return c >= 'A' && c <= 'Z' ? char(c - 'A' + 'a') : c; };
      row[j] = std::min(
          {row[j] + 1, row[j - 1] + 1, diagonal + (lower(a[i - 1]) == lower(b[j - 1]) ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

// ---- tokens

enum class TokenKind : std::uint8_t { end, number, word, quoted_name, quoted_value, symbol };

struct Token {
  TokenKind kind = TokenKind::end;
  std::string text; // the word, the symbol, or what is between the quotes
  std::size_t begin = 0, end = 0;
  std::int64_t number = 0;

  bool is(std::string_view symbol) const {
    return (kind == TokenKind::symbol || kind == TokenKind::word) && text == symbol;
  }
};

// ---- types at parse time

// `name`: an identifier that is neither a variable nor a quantifier's variable, so an
// enumeration value or set element until a comparison says whose, and an unknown
// variable anywhere else. `set_literal`: {R1, R2}, resolved the same way.
enum class Type : std::uint8_t { number, boolean, enumeration, set, bottom, name, set_literal };

struct Operand {
  Type type = Type::number;
  std::uint32_t node = 0;
  // enumeration, set: the variable whose values these are (for the value names).
  const tioa::VariableInfo* domain = nullptr;
  bool may_be_bottom = false;
  std::size_t begin = 0, end = 0; // where it is written
  std::string name;               // name: the value as written, unquoted
  bool quoted = false;            // name: written in double quotes, so surely a value
  std::vector<std::pair<std::string, std::size_t>> elements; // set_literal: names, offsets
};

constexpr std::size_t max_nesting = 200;     // parser recursion
constexpr std::size_t max_depth = 2000;      // tree depth, the evaluator's recursion
constexpr std::size_t max_nodes = 1 << 20;   // after expanding quantifiers
constexpr std::uint64_t max_range = 1 << 16; // values of one quantifier

class Parser {
public:
  Parser(const tioa::StateLayout& layout, std::string_view text) : layout_(layout), text_(text) {
    for (const auto& v : layout.variables())
      by_name_.emplace(v.name, &v);
    tokenize();
  }

  StateExpression parse() {
    if (tokens_.front().kind == TokenKind::end)
      throw ExpressionError("empty expression");
    const Operand root = parse_or();
    const Token& rest = peek();
    if (rest.kind != TokenKind::end) {
      if (comparison_op(rest) && last_was_comparison_)
        fail(rest.begin, "comparisons do not chain: write 'a < b and b < c', not 'a < b < c'");
      fail(rest.begin, "unexpected " + describe(rest) + " after '" + text_of(root) + "'");
    }
    program_.root = condition(root, "the expression");
    auto program = std::make_shared<const Program>(std::move(program_));
    StateExpression out;
    out.predicate = [program](const tioa::State& s) {
      return holds(evaluate(*program, program->root, s));
    };
    out.text = std::string(text_);
    out.variables = std::move(variables_);
    return out;
  }

private:
  // ---- errors

  [[noreturn]] void fail(std::size_t offset, const std::string& message) const {
    throw ExpressionError("column " + std::to_string(column_of(offset)) + ": " + message);
  }

  // Columns count characters from 1: UTF-8 continuation bytes do not count.
  std::size_t column_of(std::size_t offset) const {
    std::size_t column = 1;
    for (std::size_t i = 0; i < offset && i < text_.size(); ++i)
      column += (static_cast<unsigned char>(text_[i]) & 0xC0) != 0x80 ? 1 : 0;
    return column;
  }

  std::string describe(const Token& t) const {
    if (t.kind == TokenKind::end)
      return "end of expression";
    return "'" + std::string(text_.substr(t.begin, t.end - t.begin)) + "'";
  }
  std::string text_of(const Operand& o) const {
    return std::string(text_.substr(o.begin, o.end - o.begin));
  }

  // The indices that follow `prefix` ("loc[" gives 1, 2, 3) in some variable's name,
  // numbers first, in order.
  std::vector<std::string> indices_after(const std::string& prefix) const {
    std::vector<std::pair<std::int64_t, std::string>> numbers;
    std::vector<std::string> others;
    for (const auto& v : layout_.variables()) {
      if (v.name.compare(0, prefix.size(), prefix) != 0)
        continue;
      const std::size_t close = v.name.find(']', prefix.size());
      const std::string index = v.name.substr(prefix.size(), close - prefix.size());
      if (written_variable("x[" + index + "]") == "x[" + index + "]")
        numbers.emplace_back(std::stoll(index), index);
      else
        others.push_back(index);
    }
    std::sort(numbers.begin(), numbers.end());
    std::vector<std::string> out;
    for (const auto& [k, index] : numbers)
      if (out.empty() || out.back() != index)
        out.push_back(index);
    for (const auto& index : others)
      if (std::find(out.begin(), out.end(), index) == out.end())
        out.push_back(index);
    return out;
  }

  // "1..3" for a run of three or more consecutive numbers, else "0, 2, 5".
  static std::string index_text(const std::vector<std::string>& indices) {
    bool run = indices.size() >= 3;
    for (std::size_t k = 1; run && k < indices.size(); ++k)
      run = written_variable("x[" + indices[k] + "]") == "x[" + indices[k] + "]" &&
            std::stoll(indices[k]) == std::stoll(indices[0]) + std::int64_t(k);
    if (run)
      return indices.front() + ".." + indices.back();
    std::string out;
    for (const auto& index : indices)
      out += (out.empty() ? "" : ", ") + index;
    return out;
  }

  bool has_prefix(const std::string& prefix) const {
    return std::any_of(layout_.variables().begin(), layout_.variables().end(), [&](const auto& v) {
      return v.name.compare(0, prefix.size(), prefix) == 0;
    });
  }

  // `base` with its index groups `indices` (each "[k]") is no variable: says why.
  [[noreturn]] void fail_unknown(std::size_t offset, const std::string& base,
                                 const std::vector<std::string>& indices) const {
    std::string prefix = base;
    std::size_t known = 0; // how many leading index groups still lead to some variable
    while (known < indices.size() && has_prefix(prefix + indices[known])) {
      prefix += indices[known];
      ++known;
    }
    if (known < indices.size() && by_name_.count(prefix))
      fail(offset, "'" + prefix + "' is not an array, so '" + prefix + indices[known] +
                       "' is not a variable");
    if (known > 0 || has_prefix(base + "[")) {
      const std::vector<std::string> valid = indices_after(prefix + "[");
      if (known == indices.size())
        fail(offset, "'" + prefix + "' is an array: index it, as in " +
                         written_variable(prefix + "[" + valid.front() + "]") + " (indices " +
                         index_text(valid) + ")");
      fail(offset, "index " + indices[known].substr(1, indices[known].size() - 2) + " of " +
                       written_variable(prefix) + " is out of range (indices " + index_text(valid) +
                       ")");
    }
    std::string name = base;
    for (const auto& i : indices)
      name += i;
    fail(offset, "unknown variable '" + name + "'" + hint_for(name, offset));
  }

  // Near matches of an unknown name, or the first variables.
  std::string hint_for(const std::string& name, std::size_t offset) const {
    // `risk-cycle` reads as risk - cycle: an enumeration value with '-' needs quotes.
    const std::size_t after = offset + name.size();
    if (text_.substr(offset, name.size()) == name && after + 1 < text_.size() &&
        text_[after] == '-' && word_start(text_[after + 1])) {
      std::size_t end = after;
      while (end < text_.size() && (word_char(text_[end]) || text_[end] == '-'))
        ++end;
      return " (an enumeration value with '-' in it is written in double quotes: \"" +
             std::string(text_.substr(offset, end - offset)) + "\")";
    }
    // Against each name and each array's name without its indices (`lok` finds loc[1]),
    // the nearest only, one variable of an array.
    std::vector<std::pair<std::size_t, std::size_t>> near; // distance, declaration index
    const std::size_t limit = std::max<std::size_t>(1, name.size() / 3);
    const auto& all = layout_.variables();
    for (std::size_t i = 0; i < all.size(); ++i) {
      const std::string_view array = std::string_view(all[i].name).substr(0, all[i].name.find('['));
      const std::size_t d = std::min(edit_distance(name, all[i].name), edit_distance(name, array));
      if (d <= limit)
        near.emplace_back(d, i);
    }
    std::sort(near.begin(), near.end());
    std::string out;
    std::vector<std::string_view> arrays;
    for (const auto& [d, i] : near) {
      const std::string_view array = std::string_view(all[i].name).substr(0, all[i].name.find('['));
      if (d != near.front().first || arrays.size() == 3)
        break;
      if (std::find(arrays.begin(), arrays.end(), array) != arrays.end())
        continue;
      arrays.push_back(array);
      out += (out.empty() ? "" : " or ") + written_variable(all[i].name);
    }
    if (!out.empty())
      return " (did you mean " + out + "?)";
    if (all.empty())
      return " (the automaton has no variables)";
    for (std::size_t k = 0; k < all.size() && k < 5; ++k)
      out += (k == 0 ? "" : ", ") + written_variable(all[k].name);
    if (all.size() > 5)
      out += ", ... (" + std::to_string(all.size()) + " in all)";
    return " (variables: " + out + ")";
  }

  // How an enumeration value is written: as is, or in double quotes when it is not an
  // identifier or is also a variable's name.
  std::string written_value(const std::string& value) const {
    return is_plain_value(value) && !by_name_.count(value) ? value : quoted(value, '"');
  }

  std::string value_list(const tioa::VariableInfo& domain) const {
    std::string out;
    for (std::size_t k = 0; k < domain.enum_names.size(); ++k) {
      if (k == 12) {
        out += ", ... (" + std::to_string(domain.enum_names.size()) + " in all)";
        break;
      }
      out += (k == 0 ? "" : ", ") + written_value(domain.enum_names[k]);
    }
    return out;
  }

  const char* kind_name(const Operand& o) const {
    switch (o.type) {
    case Type::number:
      return "a number";
    case Type::boolean:
      return "a boolean";
    case Type::enumeration:
      return "an enumeration";
    case Type::set:
      return "a set";
    case Type::bottom:
      return "⊥";
    case Type::set_literal:
      return "a set";
    default:
      return "a value";
    }
  }

  // ---- tokens

  void tokenize() {
    std::size_t i = 0;
    while (i < text_.size()) {
      const char c = text_[i];
      if (c == ' ' || c == '\t' || c == '\n' || c == '\r') {
        ++i;
        continue;
      }
      Token t;
      t.begin = i;
      if (digit(c)) {
        t.kind = TokenKind::number;
        while (i < text_.size() && digit(text_[i])) {
          const std::int64_t d = text_[i] - '0';
          if (t.number > (std::numeric_limits<std::int64_t>::max() - d) / 10)
            fail(t.begin, "number too large: " + std::string(text_.substr(t.begin, 20)) +
                              "... (64-bit integers)");
          t.number = t.number * 10 + d;
          ++i;
        }
        if (i < text_.size() && word_start(text_[i]))
          fail(t.begin, "a name cannot start with a digit: '" +
                            std::string(text_.substr(t.begin, i + 1 - t.begin)) + "...'");
      } else if (word_start(c)) {
        t.kind = TokenKind::word;
        i += name_length(text_.substr(i));
        t.text = std::string(text_.substr(t.begin, i - t.begin));
      } else if (c == '`' || c == '"') {
        t.kind = c == '`' ? TokenKind::quoted_name : TokenKind::quoted_value;
        ++i;
        while (true) {
          if (i >= text_.size())
            fail(t.begin, std::string("unterminated ") + (c == '`' ? "name" : "value") +
                              " (no closing " + c + ")");
          if (text_[i] == c) {
            if (i + 1 < text_.size() && text_[i + 1] == c) { // a doubled quote is one quote
              t.text += c;
              i += 2;
              continue;
            }
            ++i;
            break;
          }
          t.text += text_[i++];
        }
        if (t.text.empty())
          fail(t.begin, std::string("empty ") + (c == '`' ? "name" : "value") + " " + c + c);
      } else {
        t.kind = TokenKind::symbol;
        static const char* const symbols[] = {"==", "!=", "<=", ">=", "&&", "||", "..", "⊥", "=",
                                              "<",  ">",  "!",  "+",  "-",  "*",  "/",  "%", "(",
                                              ")",  ",",  "[",  "]",  "{",  "}",  ":"};
        for (const char* s : symbols)
          if (text_.substr(i).starts_with(s)) {
            t.text = s;
            break;
          }
        if (t.text.empty()) {
          std::size_t n = 1; // the whole UTF-8 character
          while (i + n < text_.size() && (static_cast<unsigned char>(text_[i + n]) & 0xC0) == 0x80)
            ++n;
          fail(i, "unexpected character '" + std::string(text_.substr(i, n)) + "'");
        }
        i += t.text.size();
      }
      t.end = i;
      tokens_.push_back(std::move(t));
    }
    Token end;
    end.begin = end.end = text_.size();
    tokens_.push_back(end);
  }

  const Token& peek() const { return tokens_[next_]; }
  const Token& take() { return tokens_[next_ < tokens_.size() - 1 ? next_++ : next_]; }
  bool accept(std::string_view symbol) {
    if (!peek().is(symbol))
      return false;
    ++next_;
    return true;
  }
  const Token& expect(std::string_view symbol, const std::string& why) {
    if (!peek().is(symbol))
      fail(peek().begin,
           "expected '" + std::string(symbol) + "' " + why + ", found " + describe(peek()));
    return take();
  }

  static bool comparison_op(const Token& t) {
    return t.kind == TokenKind::symbol &&
           (t.text == "==" || t.text == "=" || t.text == "!=" || t.text == "<" || t.text == "<=" ||
            t.text == ">" || t.text == ">=");
  }

  // ---- nodes

  std::uint32_t add_node(Node node, std::initializer_list<std::uint32_t> children) {
    return add_node(std::move(node), std::vector<std::uint32_t>(children));
  }

  // Adds a node; one whose children are all constants is folded into a constant.
  std::uint32_t add_node(Node node, const std::vector<std::uint32_t>& children,
                         std::size_t offset = 0) {
    if (program_.nodes.size() >= max_nodes)
      fail(offset, "expression too large (more than " + std::to_string(max_nodes) +
                       " nodes after expanding quantifiers)");
    std::size_t depth = 1;
    bool constant = node.op != Op::variable;
    for (std::uint32_t c : children) {
      depth = std::max(depth, depths_[c] + 1);
      constant = constant && program_.nodes[c].op == Op::constant;
    }
    if (depth > max_depth)
      fail(offset, "expression nested too deeply");
    node.first = static_cast<std::uint32_t>(program_.children.size());
    node.count = static_cast<std::uint32_t>(children.size());
    program_.children.insert(program_.children.end(), children.begin(), children.end());
    const auto id = static_cast<std::uint32_t>(program_.nodes.size());
    program_.nodes.push_back(node);
    depths_.push_back(depth);
    if (constant && node.op != Op::constant) {
      const tioa::Word none = 0; // a constant reads no variable
      const Value v = evaluate(program_, id, tioa::State(&none, 0));
      if (v.status == Status::undefined)
        fail(offset, "integer overflow in a constant (64-bit integers)");
      program_.children.resize(node.first);
      program_.nodes.back() = constant_node(v);
      depths_.back() = 1;
    }
    return id;
  }

  static Node constant_node(Value v) {
    Node n;
    n.constant = v;
    return n;
  }
  bool is_constant(const Operand& o) const { return program_.nodes[o.node].op == Op::constant; }
  Value constant_of(const Operand& o) const { return program_.nodes[o.node].constant; }

  Operand make(Type type, std::uint32_t node, std::size_t begin, std::size_t end) const {
    Operand o;
    o.type = type;
    o.node = node;
    o.begin = begin;
    o.end = end;
    return o;
  }

  // ---- what operands must be

  // Fails unless `o` is a condition; returns its node.
  std::uint32_t condition(const Operand& o, const std::string& where) {
    if (o.type == Type::name)
      fail_name(o);
    if (o.type == Type::bottom)
      fail(o.begin, "⊥ is not a condition, but " + where + " must be one");
    if (o.type != Type::boolean)
      fail(o.begin, "'" + text_of(o) + "' is " + kind_name(o) + ", but " + where +
                        " must be a condition (true or false)");
    return o.node;
  }

  std::uint32_t number(const Operand& o, const Token& op) {
    if (o.type == Type::name)
      fail_name(o);
    if (o.type == Type::bottom)
      fail(op.begin, "'" + op.text + "' needs numbers, not ⊥");
    if (o.type != Type::number)
      fail(op.begin,
           "'" + op.text + "' needs numbers, but '" + text_of(o) + "' is " + kind_name(o));
    return o.node;
  }

  // An identifier that no comparison made a value: an unknown variable.
  [[noreturn]] void fail_name(const Operand& o) const {
    if (o.quoted)
      fail(o.begin, "the value \"" + o.name +
                        "\" must be compared with an enumeration variable (as in x = \"" + o.name +
                        "\")");
    fail_unknown(o.begin, o.name, {});
  }

  // The code of the value `name` (written at `offset`) in the enumeration or set `domain`.
  std::uint32_t value_code(const tioa::VariableInfo& domain, const std::string& name,
                           std::size_t offset) const {
    const auto& names = domain.enum_names;
    const auto it = std::find(names.begin(), names.end(), name);
    if (it == names.end())
      fail(offset, "'" + name + "' is not " +
                       (domain.kind == tioa::VariableKind::set ? "an element" : "a value") +
                       " of " + written_variable(domain.name) + " (" +
                       (domain.kind == tioa::VariableKind::set ? "elements" : "values") + ": " +
                       value_list(domain) + ")");
    return static_cast<std::uint32_t>(it - names.begin());
  }

  // Gives a `name` or `set_literal` operand the type of `other`, which it is compared with.
  Operand resolve(const Operand& o, const Operand& other, const Token& op) {
    if (o.type == Type::name) {
      if (other.type == Type::enumeration) {
        Operand out =
            make(Type::enumeration,
                 add_node(constant_node({value_code(*other.domain, o.name, o.begin)}), {}), o.begin,
                 o.end);
        out.domain = other.domain;
        return out;
      }
      if (other.type == Type::set)
        fail(op.begin, "'" + text_of(other) + "' is a set: compare it with a set, as in " +
                           text_of(other) + " = {" + o.name + "}, or write " + text_of(other) +
                           " contains " + o.name);
      if (o.quoted && other.type != Type::name)
        fail(op.begin, "'" + op.text + "' compares the value \"" + o.name + "\" with '" +
                           text_of(other) + "', which is " + kind_name(other) +
                           ", not an enumeration");
      fail_name(o);
    }
    if (o.type == Type::set_literal) {
      if (other.type == Type::name)
        fail_name(other);
      if (other.type != Type::set)
        fail(op.begin, "'" + op.text + "' compares the set " + text_of(o) + " with '" +
                           text_of(other) + "', which is " + kind_name(other) +
                           ", not a set variable");
      std::uint64_t mask = 0;
      for (const auto& [name, offset] : o.elements)
        mask |= std::uint64_t{1} << value_code(*other.domain, name, offset);
      Operand out = make(Type::set, add_node(constant_node({static_cast<std::int64_t>(mask)}), {}),
                         o.begin, o.end);
      out.domain = other.domain;
      return out;
    }
    return o;
  }

  Operand comparison(Operand a, const Token& op, Operand b) {
    const std::size_t begin = a.begin, end = b.end;
    if (op.is("contains")) {
      if (a.type == Type::name)
        fail_name(a);
      if (a.type != Type::set)
        fail(op.begin, "'contains' needs a set variable on its left, but '" + text_of(a) + "' is " +
                           kind_name(a));
      if (b.type != Type::name)
        fail(b.begin, "'contains' needs an element name on its right, such as " +
                          written_value(a.domain->enum_names.front()) + ", but found '" +
                          text_of(b) + "'");
      Node node;
      node.op = Op::contains;
      node.element = value_code(*a.domain, b.name, b.begin);
      return make(Type::boolean, add_node(node, {a.node}, op.begin), begin, end);
    }
    const bool equality = op.text == "==" || op.text == "=" || op.text == "!=";
    if (a.type == Type::name && b.type == Type::name && !a.quoted)
      fail_name(a);
    if (a.type == Type::name && b.type == Type::name)
      fail_name(b);
    if (!equality) {
      for (const Operand* o : {&a, &b}) {
        if (o->type == Type::name || o->type == Type::set_literal) {
          const Operand& other = o == &a ? b : a;
          if (other.type == Type::enumeration || other.type == Type::set) {
            fail(op.begin, "'" + op.text + "' orders '" + text_of(other) + "', which is " +
                               kind_name(other) + " and has no order");
          }
          fail_name(*o);
        }
        if (o->type == Type::bottom)
          fail(op.begin, "'" + op.text + "' with ⊥ is always false: ⊥ has no order");
        if (o->type != Type::number)
          fail(op.begin, "'" + op.text + "' orders '" + text_of(*o) + "', which is " +
                             kind_name(*o) + " and has no order");
      }
    } else {
      a = resolve(a, b, op);
      b = resolve(b, a, op);
      for (const auto& [o, other] : {std::pair{&a, &b}, std::pair{&b, &a}})
        if (o->type == Type::bottom && other->type != Type::bottom && !other->may_be_bottom)
          fail(op.begin, "'" + text_of(*other) + "' is never ⊥");
      if (a.type != b.type && a.type != Type::bottom && b.type != Type::bottom)
        fail(op.begin, "'" + op.text + "' compares " + kind_name(a) + " ('" + text_of(a) +
                           "') with " + kind_name(b) + " ('" + text_of(b) + "')");
      if ((a.type == Type::enumeration || a.type == Type::set) && a.type == b.type &&
          a.domain->enum_names != b.domain->enum_names)
        fail(op.begin, "'" + op.text + "' compares " + written_variable(a.domain->name) + " and " +
                           written_variable(b.domain->name) + ", which take different " +
                           (a.type == Type::set ? "elements" : "values"));
    }
    Node node;
    node.op = op.text == "==" || op.text == "=" ? Op::equal
              : op.text == "!="                 ? Op::not_equal
              : op.text == "<"                  ? Op::less
              : op.text == "<="                 ? Op::less_equal
              : op.text == ">"                  ? Op::greater
                                                : Op::greater_equal;
    return make(Type::boolean, add_node(node, {a.node, b.node}, op.begin), begin, end);
  }

  // ---- the grammar, loosest first

  struct Nesting {
    Parser& parser;
    Nesting(Parser& p, std::size_t offset) : parser(p) {
      if (++parser.nesting_ > max_nesting)
        parser.fail(offset, "expression nested too deeply");
    }
    ~Nesting() { --parser.nesting_; }
  };

  // and ( ('||' | 'or') and )*  (or '&&' / 'and' / ',' with `conjunction`)
  Operand parse_junction(bool conjunction) {
    Operand first = conjunction ? parse_not() : parse_junction(true);
    const auto is_op = [&](const Token& t) {
      return conjunction ? t.is("&&") || t.is("and") || t.is(",") : t.is("||") || t.is("or");
    };
    if (!is_op(peek()))
      return first;
    const std::string what = conjunction ? "each side of 'and'" : "each side of 'or'";
    std::vector<std::uint32_t> parts{condition(first, what)};
    Operand last = first;
    std::size_t offset = peek().begin;
    while (is_op(peek())) {
      take();
      last = conjunction ? parse_not() : parse_junction(true);
      parts.push_back(condition(last, what));
    }
    Node node;
    node.op = conjunction ? Op::all : Op::any;
    last_was_comparison_ = false;
    return make(Type::boolean, add_node(node, parts, offset), first.begin, last.end);
  }
  Operand parse_or() { return parse_junction(false); }

  Operand parse_not() {
    if (peek().is("!") || peek().is("not")) {
      const Token& op = take();
      const Nesting nesting(*this, op.begin);
      const Operand inner = parse_not();
      Node node;
      node.op = Op::logical_not;
      const std::uint32_t id =
          add_node(node, {condition(inner, "the operand of '" + op.text + "'")}, op.begin);
      last_was_comparison_ = false;
      return make(Type::boolean, id, op.begin, inner.end);
    }
    return parse_comparison();
  }

  Operand parse_comparison() {
    Operand left = parse_sum();
    last_was_comparison_ = false;
    if (!comparison_op(peek()) && !peek().is("contains"))
      return left;
    const Token& op = take();
    const Operand right = parse_sum();
    Operand out = comparison(left, op, right);
    last_was_comparison_ = true;
    return out;
  }

  Operand arithmetic_node(Op op_code, const Operand& a, const Token& op, const Operand& b) {
    const std::uint32_t x = number(a, op), y = number(b, op);
    if ((op_code == Op::divide || op_code == Op::remainder) && is_constant(b) &&
        constant_of(b).status == Status::known && constant_of(b).number == 0)
      fail(op.begin, "division by zero ('" + text_of(b) + "' is 0)");
    Node node;
    node.op = op_code;
    Operand out = make(Type::number, add_node(node, {x, y}, op.begin), a.begin, b.end);
    out.may_be_bottom = a.may_be_bottom || b.may_be_bottom;
    return out;
  }

  Operand parse_sum() {
    Operand left = parse_term();
    while (peek().is("+") || peek().is("-")) {
      const Token& op = take();
      const Operand right = parse_term();
      left = arithmetic_node(op.text == "+" ? Op::add : Op::subtract, left, op, right);
    }
    return left;
  }

  Operand parse_term() {
    Operand left = parse_unary();
    while (peek().is("*") || peek().is("/") || peek().is("%")) {
      const Token& op = take();
      const Operand right = parse_unary();
      left = arithmetic_node(op.text == "*"   ? Op::multiply
                             : op.text == "/" ? Op::divide
                                              : Op::remainder,
                             left, op, right);
    }
    return left;
  }

  Operand parse_unary() {
    if (!peek().is("-"))
      return parse_atom();
    const Token& op = take();
    const Nesting nesting(*this, op.begin);
    const Operand inner = parse_unary();
    Node node;
    node.op = Op::negate;
    Operand out =
        make(Type::number, add_node(node, {number(inner, op)}, op.begin), op.begin, inner.end);
    out.may_be_bottom = inner.may_be_bottom;
    return out;
  }

  Operand parse_atom() {
    const Token& t = take();
    switch (t.kind) {
    case TokenKind::end:
      fail(t.begin, "unexpected end of expression");
    case TokenKind::number:
      return make(Type::number, add_node(constant_node({t.number}), {}), t.begin, t.end);
    case TokenKind::quoted_value: {
      Operand o = make(Type::name, 0, t.begin, t.end);
      o.name = t.text;
      o.quoted = true;
      return o;
    }
    case TokenKind::quoted_name:
      return parse_variable(t);
    case TokenKind::word:
      if (t.text == "true" || t.text == "false")
        return make(Type::boolean, add_node(constant_node(truth(t.text == "true")), {}), t.begin,
                    t.end);
      if (t.text == "bottom")
        return bottom(t);
      if ((t.text == "count" || t.text == "all" || t.text == "any") &&
          (peek().is("(") || !by_name_.count(t.text)))
        return parse_quantifier(t);
      if (is_keyword(t.text))
        fail(t.begin,
             "unexpected " + describe(t) +
                 (by_name_.count(t.text) ? " (a variable named so is written `" + t.text + "`)"
                                         : ""));
      return parse_variable(t);
    case TokenKind::symbol:
      break;
    }
    if (t.text == "⊥")
      return bottom(t);
    if (t.text == "(") {
      const Nesting nesting(*this, t.begin);
      Operand inner = parse_or();
      const Token& close =
          expect(")", "to close the '(' at column " + std::to_string(column_of(t.begin)));
      inner.begin = t.begin;
      inner.end = close.end;
      last_was_comparison_ = false;
      return inner;
    }
    if (t.text == "{")
      return parse_set(t);
    fail(t.begin, "unexpected " + describe(t));
  }

  Operand bottom(const Token& t) {
    return make(Type::bottom, add_node(constant_node({0, Status::bottom}), {}), t.begin, t.end);
  }

  // An integer known at parse time (an index or a range bound).
  std::int64_t constant_integer(const Operand& o, const std::string& what) {
    if (o.type == Type::name && !o.quoted)
      fail(o.begin, what + " must be an integer constant or a quantifier's variable, but '" +
                        o.name + "' is neither");
    if (o.type != Type::number)
      fail(o.begin, what + " must be an integer, but '" + text_of(o) + "' is " + kind_name(o));
    if (!is_constant(o) || constant_of(o).status != Status::known)
      fail(o.begin, what + " must be an integer constant or a quantifier's variable, but '" +
                        text_of(o) + "' reads the state");
    return constant_of(o).number;
  }

  const std::int64_t* bound(const std::string& name) const {
    for (auto it = bound_.rbegin(); it != bound_.rend(); ++it)
      if (it->first == name)
        return &it->second;
    return nullptr;
  }

  // name ( '[' sum ']' )*, or a quantifier's variable, or else an enumeration value.
  Operand parse_variable(const Token& first) {
    if (first.kind == TokenKind::word && !peek().is("["))
      if (const std::int64_t* value = bound(first.text))
        return make(Type::number, add_node(constant_node({*value}), {}), first.begin, first.end);
    std::vector<std::string> indices;
    std::size_t end = first.end;
    while (peek().is("[")) {
      const Token& open = take();
      const Nesting nesting(*this, open.begin);
      const std::int64_t k = constant_integer(parse_sum(), "an index");
      end = expect("]", "to close the '[' at column " + std::to_string(column_of(open.begin))).end;
      indices.push_back("[" + std::to_string(k) + "]");
    }
    std::string name = first.text;
    for (const auto& i : indices)
      name += i;
    const auto found = by_name_.find(name);
    if (found == by_name_.end()) {
      if (first.kind == TokenKind::word && indices.empty()) {
        Operand o = make(Type::name, 0, first.begin, end);
        o.name = first.text;
        return o;
      }
      fail_unknown(first.begin, first.text, indices);
    }
    const tioa::VariableInfo& info = *found->second;
    if (std::find(variables_.begin(), variables_.end(), info.name) == variables_.end())
      variables_.push_back(info.name);
    Node node;
    node.op = Op::variable;
    node.slot = info.slot();
    Operand o = make(Type::number, add_node(node, {}), first.begin, end);
    switch (info.kind) {
    case tioa::VariableKind::boolean:
      o.type = Type::boolean;
      break;
    case tioa::VariableKind::enumeration:
      o.type = Type::enumeration;
      break;
    case tioa::VariableKind::set:
      o.type = Type::set;
      break;
    default:
      break;
    }
    o.domain = &info;
    o.may_be_bottom = info.has_bottom;
    return o;
  }

  // '{' [ value ( ',' value )* ] '}'
  Operand parse_set(const Token& open) {
    Operand o = make(Type::set_literal, 0, open.begin, open.end);
    if (!peek().is("}")) {
      do {
        const Token& t = take();
        if (!(t.kind == TokenKind::quoted_value ||
              (t.kind == TokenKind::word && !is_keyword(t.text))))
          fail(t.begin, "expected an element name in the set, found " + describe(t));
        o.elements.emplace_back(t.text, t.begin);
      } while (accept(","));
    }
    o.end = expect("}", "to close the '{' at column " + std::to_string(column_of(open.begin))).end;
    return o;
  }

  // ('count' | 'all' | 'any') '(' name 'in' sum '..' sum ':' or ')', expanded over the range.
  Operand parse_quantifier(const Token& keyword) {
    const Nesting nesting(*this, keyword.begin);
    expect("(", "after '" + keyword.text + "', as in " + keyword.text + "(i in 1..3: x[i] = 0)");
    const Token& variable = take();
    if (variable.kind != TokenKind::word || is_keyword(variable.text) ||
        variable.text.find('.') != std::string::npos)
      fail(variable.begin,
           "expected the name of the quantifier's variable, found " + describe(variable));
    expect("in", "after the quantifier's variable '" + variable.text + "'");
    const Operand lo_operand = parse_sum();
    const std::int64_t lo = constant_integer(lo_operand, "the range's lower bound");
    expect("..", "in the range, as in 1..3");
    const Operand hi_operand = parse_sum();
    const std::int64_t hi = constant_integer(hi_operand, "the range's upper bound");
    if (hi < lo)
      fail(lo_operand.begin, "empty range " + std::to_string(lo) + ".." + std::to_string(hi));
    const std::uint64_t values =
        static_cast<std::uint64_t>(hi) - static_cast<std::uint64_t>(lo) + 1;
    if (values == 0 || values > max_range) // 0: the whole of int64
      fail(lo_operand.begin, "range " + std::to_string(lo) + ".." + std::to_string(hi) +
                                 " too long (at most " + std::to_string(max_range) + " values)");
    expect(":", "after the range");
    const std::size_t body = next_;
    std::vector<std::uint32_t> parts;
    for (std::uint64_t k = 0; k < values; ++k) {
      next_ = body;
      bound_.emplace_back(variable.text,
                          static_cast<std::int64_t>(static_cast<std::uint64_t>(lo) + k));
      const Operand inner = parse_or();
      parts.push_back(condition(inner, "the body of '" + keyword.text + "'"));
      bound_.pop_back();
    }
    const Token& close = expect(")", "to close '" + keyword.text + "(' at column " +
                                         std::to_string(column_of(keyword.begin)));
    Node node;
    node.op = keyword.text == "count" ? Op::count : keyword.text == "all" ? Op::all : Op::any;
    last_was_comparison_ = false;
    return make(node.op == Op::count ? Type::number : Type::boolean,
                add_node(node, parts, keyword.begin), keyword.begin, close.end);
  }

  const tioa::StateLayout& layout_;
  std::string_view text_;
  std::unordered_map<std::string, const tioa::VariableInfo*> by_name_;
  std::vector<Token> tokens_;
  std::size_t next_ = 0;
  Program program_;
  std::vector<std::size_t> depths_; // of each node
  std::vector<std::pair<std::string, std::int64_t>> bound_;
  std::vector<std::string> variables_;
  std::size_t nesting_ = 0;
  bool last_was_comparison_ = false;
};

} // namespace

StateExpression parse_state_expression(const tioa::StateLayout& layout, std::string_view text) {
  return Parser(layout, text).parse();
}

} // namespace checker
