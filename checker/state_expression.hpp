#pragma once
// A small expression language over the state variables of an automaton, for conditions
// written on the command line: an ad-hoc invariant (`--invariant 'count(i in 1..3: loc[i] =
// CS) <= 1'`) or a start predicate (`--start 'id = 0, loc[1] = REQ'`). The text is parsed and
// type-checked once against the automaton's layout into a small tree of slots and
// constants; evaluating it on a state reads codes only, never throws and never allocates.
//
// Grammar, loosest first (whitespace is free):
//   or    := and ( ('||' | 'or') and )*
//   and   := not ( ('&&' | 'and' | ',') not )*     a comma is "and": 'a = 1, b = 2'
//   not   := ('!' | 'not') not | cmp                 so '!a = b' is '!(a = b)'
//   cmp   := sum [ ('==' | '=' | '!=' | '<' | '<=' | '>' | '>=' | 'contains') sum ]
//   sum   := term ( ('+' | '-') term )*
//   term  := unary ( ('*' | '/' | '%') unary )*
//   unary := '-' unary | atom
//   atom  := integer | 'true' | 'false' | 'bottom' | '⊥' | variable | value | set
//          | '(' or ')' | ('count' | 'all' | 'any') '(' name 'in' sum '..' sum ':' or ')'
//   variable := name ( '[' sum ']' )* | '`' any text '`' ( '[' sum ']' )*
//   name  := word ( '.' [A-Za-z0-9_]+ )*   word := [A-Za-z_][A-Za-z0-9_]*
//   value := word | '"' any text '"'          an enumeration value or set element
//   set   := '{' [ value ( ',' value )* ] '}'  e.g. G[1] = {R1, R2}, G[1] = {}
//
// Variables. `loc[1]`, `net.OK[1][2]`: the indices are integer constants or quantifier
// variables (`loc[i + 1]`) and are folded at parse time, so `loc[ 1 ]` is `loc[1]`. A name
// that is not written this way (one that holds other characters, `x[01]`, or a keyword) is
// written between backquotes, verbatim: `` `A||B.x` ``; a backquote inside is doubled.
// Keywords: and or not true false bottom count all any in contains.
//
// Values. Integers are 64-bit; integer and clock variables read lo + code. An identifier
// that is not a variable (nor a quantifier's variable) is an enumeration value, resolved
// against the enumeration it is compared with; a value that is not an identifier
// (`risk-cycle`) or is also a variable's name is written in double quotes ("risk-cycle").
// Set variables compare with sets (`G[1] = {R1}`) and test an element (`G[1] contains R2`).
//
// ⊥ equals only ⊥; ordering with ⊥ is false; arithmetic with ⊥ gives ⊥ (so `x + 1 = ⊥`
// holds when x is ⊥). A boolean that is ⊥ does not hold. Division and remainder truncate
// toward zero, as in C++. A division by zero at run time, or a result beyond 64 bits, is
// undefined and makes every comparison it takes part in false (`!=` too).
//
// Quantifiers expand at parse time over a range of integer constants: count(i in 1..3: c)
// is the number of i for which c holds, all(...) their conjunction, any(...) their
// disjunction. Inside, `i` is an integer constant; it hides a variable of the same name.
//
// Type errors are parse errors: a number compared with a boolean, an enumeration ordered
// with <, arithmetic on booleans or enumerations, a top-level expression that is not a
// condition, division by the constant 0, ⊥ compared with a variable that is never ⊥, an
// index outside an array, an enumeration value its variable does not have.

#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "tioa/start_set.hpp"
#include "tioa/variables.hpp"

namespace checker {

// A malformed expression: what() is one line that says what is wrong and where, e.g.
// "column 7: unknown variable 'lok[1]' (did you mean loc[1]?)".
class ExpressionError : public std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

struct StateExpression {
  tioa::StatePredicate predicate;     // holds on a state (a view at the automaton's base)
  std::string text;                   // the expression as given
  std::vector<std::string> variables; // the variable names it reads, in first-use order, once each
};

// Parses `text` against the variables of `layout`. Throws ExpressionError.
StateExpression parse_state_expression(const tioa::StateLayout& layout, std::string_view text);

} // namespace checker
