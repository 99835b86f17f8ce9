#!/usr/bin/env python3
"""Independent brute-force reference enumerator for the two peer models.

Source of truth: /work/shared/peer-models.md.  Plain Python 3, standard library
only.  Every figure is computed by explicit enumeration of the concrete state
graph (processes distinguishable, no symmetry reduction).  It is meant as an
independent cross-check for the C++ engine of tioa-check, so it shares no code
or encoding with it.

Usage:  python3 tools/reference/peer_models.py [--table] [--skip-large]

Prints one JSON object on stdout; with --table a readable table is printed
after it.  --skip-large drops Dijkstra (8,7) (5.7 M states, the slow one).

"Edges" (both models) = the sum over reachable states of the number of enabled
actions, self-loops included; two actions with the same target count twice.

(a) Dijkstra's K-state self-stabilising token ring -- spec rules quoted:
    - State: x[0..N-1], each in 0..K-1; nothing else.
    - Start states: all K^N assignments (this is U(A)).
    - Actions, interleaved (one per step, any enabled one):
      - process 0: enabled iff x[0] == x[N-1]; effect x[0] := (x[0] + 1) mod K;
      - process i, 1 <= i < N: enabled iff x[i] != x[i-1]; effect x[i] := x[i-1].
    - Legal set L: exactly one process is privileged.
    - (Time here is steps: each action takes one unit.)
  "Privileged" = has an enabled action.  Here every action changes the state,
  so the Dijkstra graph has no self-loops.
  Figures per (N, K):
    states, edges, deadlocks (states with no enabled action, outside or in L);
    |L|, L closed;
    convergence to L from every state (no deadlock outside L and no cycle of
    non-L states; all states are start states, so all are reachable);
    worst_steps = max over all executions of the number of steps until the
    first state in L (0 if the start state is in L), with the smallest start
    state (lexicographic on x[0..N-1]) that attains it;
    if convergence fails: the shortest lasso.  Because every state is a start
    state, a shortest lasso has an empty stem (length 0) and its cycle is a
    shortest cycle through non-L states; cycle length = lasso length.  We also
    report how many states can run forever outside L ("diverging" states:
    non-L states with an infinite non-L path).
    L1 = "at most 2 privileged": closed or not, convergence to L1 and worst
    steps from all states to L1, and worst steps to L from L1 states only.

(b) Fischer's mutual exclusion in discrete time -- spec rules quoted:
    - State: shared id in 0..N (0 = free); per process p a location loc[p] in
      {IDLE, REQ, WAIT, CS} and an integer clock c[p] in 0..CMAX.
    - One start state: id = 0, every loc[p] = IDLE, every c[p] = 0.
    - CMAX = max(A, B) + 1.
    - Actions of process p (interleaved, each atomic):
        try   | loc[p] == IDLE && id == 0          | loc[p] := REQ;  c[p] := 0
        set   | loc[p] == REQ                      | loc[p] := WAIT; id := p; c[p] := 0
        enter | loc[p] == WAIT && c[p] >= B && id == p | loc[p] := CS; c[p] := 0
        fail  | loc[p] == WAIT && c[p] >= B && id != p | loc[p] := IDLE; c[p] := 0
        exit  | loc[p] == CS                       | loc[p] := IDLE; id := 0
    - Time passes by a global tick (one atomic step):
      - enabled iff no process is in REQ with c[p] >= A (urgency);
      - effect: for each p with loc[p] in {REQ, WAIT}:
        c[p] := min(c[p] + 1, CMAX); clocks of IDLE and CS processes stay 0.
      - A tick is enabled even when it changes nothing: such a tick is a
        self-loop and counts as an edge.
    - Invariant: mutual exclusion (at most one p with loc[p] == CS).
  Figures per (N, A, B): reachable states (breadth-first from the start state;
  states violating mutual exclusion are explored further like any other),
  edges, self-loops (ticks that change nothing), deadlocks (no action and no
  tick enabled), whether mutual exclusion holds, the number of reachable
  violating states, and the length (actions, ticks included) of a shortest
  trace to a violating state.  The printed trace is the one found by BFS with
  successor order: process 1..N, each in the order try, set, enter, fail,
  exit; then tick (the length is canonical, the trace itself is one of
  possibly several shortest ones).
"""

import itertools
import json
import sys
import time
from array import array
from collections import deque

# --------------------------------------------------------------------------
# (a) Dijkstra's K-state token ring
# --------------------------------------------------------------------------
# A state x[0..N-1] is encoded as the integer sum x[i] * K^(N-1-i), so that
# itertools.product(range(K), repeat=N) enumerates codes 0, 1, 2, ... in order
# and integer order equals lexicographic order on x[0..N-1].

DIJKSTRA_INSTANCES = [(3, 2), (3, 3), (4, 3), (4, 4), (5, 4), (5, 5), (6, 5),
                      (4, 2), (5, 3), (6, 4), (7, 6), (8, 7)]
LARGE_DIJKSTRA = {(8, 7)}


class Ring:
    """The state graph of Dijkstra's ring for fixed (N, K)."""

    def __init__(self, n, k):
        self.n, self.k = n, k
        self.total = k ** n
        self.weight = [k ** (n - 1 - i) for i in range(n)]

    def decode(self, s):
        x = [0] * self.n
        for i in range(self.n - 1, -1, -1):
            s, x[i] = divmod(s, self.k)
        return x

    def privileged(self, x):
        """Indices of privileged (enabled) processes, in index order."""
        n = self.n
        out = [0] if x[0] == x[n - 1] else []
        out.extend(i for i in range(1, n) if x[i] != x[i - 1])
        return out

    def successors(self, s):
        """Successor codes, one per enabled action, in process order 0..N-1."""
        n, k, w = self.n, self.k, self.weight
        x = self.decode(s)
        out = []
        if x[0] == x[n - 1]:
            out.append(s + ((x[0] + 1) % k - x[0]) * w[0])
        for i in range(1, n):
            if x[i] != x[i - 1]:
                out.append(s + (x[i - 1] - x[i]) * w[i])
        return out

    def privilege_counts(self):
        """bytearray: number of privileged processes per state code."""
        n = self.n
        cnt = bytearray(self.total)
        for s, x in enumerate(itertools.product(range(self.k), repeat=n)):
            c = 1 if x[0] == x[n - 1] else 0
            for i in range(1, n):
                if x[i] != x[i - 1]:
                    c += 1
            cnt[s] = c
        return cnt


UNKNOWN, ON_STACK = -1, -2


def longest_to_target(ring, in_target, roots=None):
    """Longest number of steps from each state until the first target state.

    in_target: bytes-like, nonzero = state is in the target set.
    roots: the states to start from (default: all states); only states
    reachable from them are explored, and a cycle counts only if reachable.
    Returns (dist, cyclic): dist is an array with dist[s] = max over executions
    from s of steps to the first target state (0 for target states); cyclic is
    True if some cycle of non-target states exists (then dist is incomplete).
    Deadlocks outside the target are not possible here (checked separately);
    they would simply get dist 0 and are reported by the caller.
    """
    total = ring.total
    succ = ring.successors
    dist = array('i', [UNKNOWN]) * total
    for root in (range(total) if roots is None else roots):
        if dist[root] != UNKNOWN:
            continue
        if in_target[root]:
            dist[root] = 0
            continue
        dist[root] = ON_STACK
        stack = [[root, iter(succ(root)), 0]]
        while stack:
            frame = stack[-1]
            pushed = False
            for t in frame[1]:
                d = dist[t]
                if d == UNKNOWN:
                    if in_target[t]:
                        dist[t] = d = 0
                    else:
                        dist[t] = ON_STACK
                        stack.append([t, iter(succ(t)), 0])
                        pushed = True
                        break
                elif d == ON_STACK:
                    return dist, True
                if d + 1 > frame[2]:
                    frame[2] = d + 1
            if pushed:
                continue
            stack.pop()
            dist[frame[0]] = frame[2]
            if stack and frame[2] + 1 > stack[-1][2]:
                stack[-1][2] = frame[2] + 1
    return dist, False


def diverging_states(ring, in_target):
    """Number of non-target states with an infinite path avoiding the target.

    Greatest fixpoint: repeatedly drop non-target states none of whose
    successors is a still-kept non-target state.  Only used on the (small)
    failing instances.
    """
    keep = bytearray(0 if in_target[s] else 1 for s in range(ring.total))
    succs = {s: ring.successors(s) for s in range(ring.total) if keep[s]}
    changed = True
    while changed:
        changed = False
        for s, ts in succs.items():
            if keep[s] and not any(keep[t] for t in ts):
                keep[s] = 0
                changed = True
    return sum(keep)


def shortest_cycle_outside(ring, in_target):
    """Shortest cycle through non-target states: (length, [state codes]).

    BFS from every non-target state s (in increasing code order) inside the
    non-target subgraph, looking for the shortest path back to s.  The first
    cycle of minimum length found is returned, starting at its smallest-code
    state s.  None if there is no such cycle.
    """
    best = None
    for s in range(ring.total):
        if in_target[s]:
            continue
        parent = {s: None}
        queue = deque([(s, 0)])
        found = None
        while queue and found is None:
            u, d = queue.popleft()
            if best is not None and d + 1 >= best[0]:
                break
            for t in ring.successors(u):
                if in_target[t]:
                    continue
                if t == s:
                    found = (d + 1, u)
                    break
                if t not in parent:
                    parent[t] = u
                    queue.append((t, d + 1))
        if found is not None and (best is None or found[0] < best[0]):
            path = []
            u = found[1]
            while u is not None:
                path.append(u)
                u = parent[u]
            path.reverse()
            best = (found[0], path)
    return best


def max_with_witness(dist, states):
    """(max dist over the given state codes, smallest code attaining it)."""
    best, arg = -1, None
    for s in states:
        if dist[s] > best:
            best, arg = dist[s], s
    return best, arg


def check_dijkstra(n, k):
    ring = Ring(n, k)
    cnt = ring.privilege_counts()
    total = ring.total
    in_l = bytes(1 if c == 1 else 0 for c in cnt)
    in_l1 = bytes(1 if c <= 2 else 0 for c in cnt)
    edges = sum(cnt)
    deadlocks = cnt.count(0)
    size_l = sum(in_l)
    size_l1 = sum(in_l1)

    # Closure: every action from every state of the set stays in the set.
    l_closed = all(in_l[t] for s in range(total) if in_l[s]
                   for t in ring.successors(s))
    l1_closed = all(in_l1[t] for s in range(total) if in_l1[s]
                    for t in ring.successors(s))

    res = {
        "N": n, "K": k, "states": total, "edges": edges,
        "deadlocks": deadlocks,
        "deadlocks_outside_L": sum(1 for s in range(total)
                                   if cnt[s] == 0 and not in_l[s]),
        "L_size": size_l, "L_closed": l_closed,
        "L1_size": size_l1, "L1_closed": l1_closed,
    }

    # Convergence to L.
    dist, cyclic = longest_to_target(ring, in_l)
    res["converges"] = (not cyclic) and res["deadlocks_outside_L"] == 0
    if not cyclic:
        w, arg = max_with_witness(dist, range(total))
        res["worst_steps"] = w
        res["worst_steps_witness_start"] = ring.decode(arg)
    else:
        res["worst_steps"] = None
        length, cycle = shortest_cycle_outside(ring, in_l)
        res["shortest_lasso"] = {
            "stem_length": 0, "cycle_length": length,
            "total_length": length,
            "cycle": [ring.decode(s) for s in cycle],
        }
        res["diverging_states"] = diverging_states(ring, in_l)

    # Convergence to L1, from all states.
    dist1, cyclic1 = longest_to_target(ring, in_l1)
    res["converges_to_L1"] = not cyclic1
    res["worst_steps_to_L1"] = (None if cyclic1
                                else max_with_witness(dist1, range(total))[0])

    # From L1 states only, to L (a search rooted at the L1 states only, so
    # that cycles outside L that L1 cannot reach do not matter).
    l1_states = [s for s in range(total) if in_l1[s]]
    if cyclic:
        dist, cyclic_l1 = longest_to_target(ring, in_l, roots=l1_states)
    else:
        cyclic_l1 = False
    res["converges_from_L1_to_L"] = not cyclic_l1
    if not cyclic_l1:
        w, arg = max_with_witness(dist, l1_states)
        res["worst_steps_L1_to_L"] = w
        res["worst_steps_L1_to_L_witness_start"] = ring.decode(arg)
    else:
        res["worst_steps_L1_to_L"] = None
    return res


# --------------------------------------------------------------------------
# (b) Fischer's mutual exclusion in discrete time
# --------------------------------------------------------------------------
# A state is the tuple (id, loc[1], ..., loc[N], c[1], ..., c[N]).

IDLE, REQ, WAIT, CS = 0, 1, 2, 3
LOC_NAMES = ("IDLE", "REQ", "WAIT", "CS")

FISCHER_INSTANCES = ([(n, 1, 2) for n in (2, 3, 4, 5, 6)]
                     + [(n, 2, 2) for n in (2, 3)]
                     + [(n, 2, 1) for n in (2, 3)])


def fischer_successors(state, n, a, b, cmax):
    """List of (label, successor) for every enabled action, tick last."""
    ident = state[0]
    loc = state[1:n + 1]
    clk = state[n + 1:]
    out = []

    def make(p, new_loc, new_clk, new_id):
        ls = list(loc)
        cs = list(clk)
        ls[p - 1] = new_loc
        cs[p - 1] = new_clk
        return (new_id,) + tuple(ls) + tuple(cs)

    for p in range(1, n + 1):
        lp, cp = loc[p - 1], clk[p - 1]
        if lp == IDLE and ident == 0:
            out.append(("try(%d)" % p, make(p, REQ, 0, ident)))
        if lp == REQ:
            out.append(("set(%d)" % p, make(p, WAIT, 0, p)))
        if lp == WAIT and cp >= b and ident == p:
            out.append(("enter(%d)" % p, make(p, CS, 0, ident)))
        if lp == WAIT and cp >= b and ident != p:
            out.append(("fail(%d)" % p, make(p, IDLE, 0, ident)))
        if lp == CS:
            # Effect per spec: loc := IDLE; id := 0 (clock untouched; a CS
            # clock is always 0 anyway).
            out.append(("exit(%d)" % p, make(p, IDLE, cp, 0)))
    # Tick: urgency -- blocked iff some REQ process has c >= A.
    if not any(loc[i] == REQ and clk[i] >= a for i in range(n)):
        new_clk = tuple(min(clk[i] + 1, cmax) if loc[i] in (REQ, WAIT)
                        else clk[i] for i in range(n))
        out.append(("tick", (ident,) + tuple(loc) + new_clk))
    return out


def fischer_violates(state, n):
    return sum(1 for l in state[1:n + 1] if l == CS) >= 2


def fischer_state_str(state, n):
    parts = ["id=%d" % state[0]]
    for p in range(1, n + 1):
        parts.append("P%d=%s/c%d" % (p, LOC_NAMES[state[p]], state[n + p]))
    return " ".join(parts)


def check_fischer(n, a, b):
    cmax = max(a, b) + 1
    start = (0,) + (IDLE,) * n + (0,) * n
    parent = {start: None}          # state -> (predecessor, label)
    queue = deque([start])
    edges = self_loops = deadlocks = violating = 0
    first_bad = None
    while queue:
        s = queue.popleft()
        succ = fischer_successors(s, n, a, b, cmax)
        edges += len(succ)
        if not succ:
            deadlocks += 1
        if fischer_violates(s, n):
            violating += 1
            if first_bad is None:
                first_bad = s       # BFS order: minimal depth
        for label, t in succ:
            if t == s:
                self_loops += 1
            if t not in parent:
                parent[t] = (s, label)
                queue.append(t)
    res = {
        "N": n, "A": a, "B": b, "CMAX": cmax,
        "states": len(parent), "edges": edges, "self_loops": self_loops,
        "deadlocks": deadlocks,
        "mutex_holds": first_bad is None,
        "violating_states": violating,
    }
    if first_bad is not None:
        trace = []
        s = first_bad
        while parent[s] is not None:
            pred, label = parent[s]
            trace.append((label, s))
            s = pred
        trace.reverse()
        res["shortest_cex_length"] = len(trace)
        res["shortest_cex"] = (
            [{"action": None, "state": fischer_state_str(start, n)}]
            + [{"action": lab, "state": fischer_state_str(t, n)}
               for lab, t in trace])
    return res


# --------------------------------------------------------------------------
# Output
# --------------------------------------------------------------------------

def fmt(v):
    if v is None:
        return "-"
    if v is True:
        return "yes"
    if v is False:
        return "no"
    return str(v)


def inf(v):
    """Worst-case step count; None means some execution never arrives."""
    return "inf" if v is None else str(v)


def print_table(out):
    dj = out["dijkstra"]
    print()
    print("Dijkstra K-state ring (L = exactly one privileged, "
          "L1 = at most two privileged)")
    hdr = ("N", "K", "states", "edges", "|L|", "L clos", "conv",
           "worst", "lasso", "diverg", "|L1|", "L1 clos", "worst->L1",
           "L1->L")
    rows = []
    for r in dj:
        lasso = r.get("shortest_lasso")
        rows.append((r["N"], r["K"], r["states"], r["edges"], r["L_size"],
                     fmt(r["L_closed"]), fmt(r["converges"]),
                     inf(r["worst_steps"]),
                     "0+%d" % lasso["cycle_length"] if lasso else "-",
                     fmt(r.get("diverging_states")),
                     r["L1_size"], fmt(r["L1_closed"]),
                     inf(r["worst_steps_to_L1"]),
                     inf(r["worst_steps_L1_to_L"])))
    print_rows(hdr, rows)
    print("  conv = every execution from every state reaches L; worst = max"
          " steps to the first L state;")
    print("  lasso = stem+cycle length of a shortest lasso; diverg = non-L"
          " states with an infinite non-L path;")
    print("  worst->L1 = max steps from any state to L1; L1->L = max steps"
          " to L from L1 states; inf = some execution never arrives.")
    print("  deadlocks: %s (all instances)"
          % sorted({r["deadlocks"] for r in dj}))
    for r in dj:
        print("  (%d,%d) worst-case start x=%s ; from L1: x=%s"
              % (r["N"], r["K"], r.get("worst_steps_witness_start", "-"),
                 r.get("worst_steps_L1_to_L_witness_start", "-")))
    failing = [r for r in dj if not r["converges"]]
    if failing:
        r = min(failing, key=lambda r: r["states"])
        lasso = r["shortest_lasso"]
        print("  Shortest lasso for the smallest failing instance (N=%d, K=%d):"
              % (r["N"], r["K"]))
        print("    stem: (empty; every state is a start state)")
        print("    cycle (%d steps): %s -> back to %s"
              % (lasso["cycle_length"],
                 " -> ".join(str(x) for x in lasso["cycle"]),
                 lasso["cycle"][0]))
    for r in failing:
        lasso = r["shortest_lasso"]
        print("  (%d,%d) shortest cycle outside L: %s"
              % (r["N"], r["K"], " -> ".join(str(x) for x in lasso["cycle"])))

    print()
    print("Fischer, discrete time (tick counted as one action)")
    hdr = ("N", "A", "B", "CMAX", "states", "edges", "tick-loops",
           "deadlocks", "mutex", "bad states", "cex len")
    rows = [(r["N"], r["A"], r["B"], r["CMAX"], r["states"], r["edges"],
             r["self_loops"], r["deadlocks"], fmt(r["mutex_holds"]),
             r["violating_states"], fmt(r.get("shortest_cex_length")))
            for r in out["fischer"]]
    print_rows(hdr, rows)
    for r in out["fischer"]:
        if r["N"] == 2 and "shortest_cex" in r:
            print("  Shortest counterexample N=2, A=%d, B=%d (%d steps):"
                  % (r["A"], r["B"], r["shortest_cex_length"]))
            for i, step in enumerate(r["shortest_cex"]):
                print("    %2d %-9s %s" % (i, step["action"] or "(start)",
                                         step["state"]))
    print()
    print("Total run time: %.1f s" % out["run_time_seconds"])


def print_rows(hdr, rows):
    cols = list(zip(hdr, *rows))
    widths = [max(len(str(v)) for v in col) for col in cols]
    line = "  ".join(str(h).rjust(w) for h, w in zip(hdr, widths))
    print(line)
    print("-" * len(line))
    for row in rows:
        print("  ".join(str(v).rjust(w) for v, w in zip(row, widths)))


def main(argv):
    table = "--table" in argv
    skip_large = "--skip-large" in argv
    t0 = time.time()
    out = {"dijkstra": [], "fischer": []}
    for n, k in DIJKSTRA_INSTANCES:
        if skip_large and (n, k) in LARGE_DIJKSTRA:
            continue
        t = time.time()
        r = check_dijkstra(n, k)
        r["seconds"] = round(time.time() - t, 2)
        out["dijkstra"].append(r)
    for n, a, b in FISCHER_INSTANCES:
        t = time.time()
        r = check_fischer(n, a, b)
        r["seconds"] = round(time.time() - t, 2)
        out["fischer"].append(r)
    out["run_time_seconds"] = round(time.time() - t0, 2)
    print(json.dumps(out, indent=1))
    if table:
        print_table(out)


if __name__ == "__main__":
    main(sys.argv[1:])
