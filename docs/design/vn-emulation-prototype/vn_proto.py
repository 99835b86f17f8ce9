#!/usr/bin/env python3
"""Throw-away explicit-state prototype of the seed-002 §VIII VN emulation
(TOBcast + VNE + LBcast + trivial clients), ONE zone, N physical nodes.

It exists only to size the state space and to sanity-check the decisions of
../vn-emulation.md (D-numbers below refer to that file).  It is not part
of tioa-check and is not a reference implementation.

Time: integer quanta.  All timestamps are stored relative to "now" (<= 0) and
aged at each tick, so the state carries no absolute time (spec §5.1).
Positions: one zone; leaving B / crashing = fail, entering / restarting =
recover (002:35 "We model the departure of a node from B as a failure").
"""
import sys, argparse
from collections import deque

ap = argparse.ArgumentParser()
ap.add_argument('--N', type=int, default=2)
ap.add_argument('--dp', type=int, default=1)
ap.add_argument('--eps', type=int, default=1)
ap.add_argument('--M', type=int, default=1, help='client message budget (total)')
ap.add_argument('--F', type=int, default=1, help='fail budget (total)')
ap.add_argument('--K', type=int, default=2, help='counter modulus')
ap.add_argument('--S', type=int, default=4, help='send-sequence modulus')
ap.add_argument('--start', choices=['cold', 'warm'], default='cold')
ap.add_argument('--vn', choices=['fifo', 'report'], default='fifo',
                help='fifo: sends come from a FIFO buffer (as Fig. 6); report: send the current value')
ap.add_argument('--L', type=int, default=2, help='FIFO capacity')
ap.add_argument('--record', choices=['executed', 'always'], default='executed',
                help='D-completed: record completed-actions only when executed (printed indentation) or always')
ap.add_argument('--quiescent_ack', type=int, default=1, help='ack-join needs a quiescent VN (as printed)')
ap.add_argument('--reset_val', type=int, default=1, help='reset sets val to start (prose 002:352)')
ap.add_argument('--max_states', type=int, default=3_000_000)
ap.add_argument('--por', type=int, default=1, help='expand only one PN\'s steps inside a zero-time burst')
ap.add_argument('--env_at_ticks', type=int, default=1,
                help='environment inputs (fail/recover/cn-send) only at states where time can pass')
A = ap.parse_args()

N, DP, EPS = A.N, A.dp, A.eps
TOBD = DP + EPS                 # TOBcast delivery delay (002:348)
JOINWAIT = 3 * DP + 4 * EPS     # restart precondition (002:432)
DMMT, DR, DV = 2 * DP + 2 * EPS, 4 * DP + 5 * EPS, 2 * DP + EPS
H = 4 * DP + 4 * EPS + 2        # GC horizon for completed-actions / dedup sets (D-GC)
CAP = H + 2                     # ages saturate here

# counter VN.  report: (count mod K, last sender, dirty, send seq mod S)
#              fifo:   (count mod K, last sender, FIFO of (count,last), send seq mod S)
START = (0, None, False, 0) if A.vn == 'report' else (0, None, (), 0)


def vn_enabled(v):
    c, l, d, q = v
    if A.vn == 'report':
        return ('send', (c, l, q)) if d else None
    return ('send', d[0]) if d else None


def vn_delta(v, act):
    c, l, d, q = v
    if act[0] == 'recv':
        if A.vn == 'report':
            return ((c + 1) % A.K, act[2], True, q)
        c2 = (c + 1) % A.K
        assert len(d) < A.L, 'FIFO overflow: raise --L'
        return (c2, act[2], d + ((c2, act[2]),), q)
    if act[0] == 'send':
        if vn_enabled(v) == act:
            return (c, l, False if A.vn == 'report' else d[1:], (q + 1) % A.S)
        return None
    raise ValueError(act)


def T(k):
    return ('t', max(k, -CAP))


def age(x):
    """Age every timestamp inside a nested tuple/frozenset by one quantum."""
    if isinstance(x, tuple):
        if len(x) == 2 and x[0] == 't':
            return ('t', max(x[1] - 1, -CAP))
        return tuple(age(y) for y in x)
    if isinstance(x, frozenset):
        return frozenset(age(y) for y in x)
    return x


def tv(x):
    return x[1]


def tmax(a, b):
    if a is None:
        return b
    if b is None:
        return a
    return a if tv(a) >= tv(b) else b


def tgt(a, b):  # a > b with None = -infinity (D: initial pending/completed-join)
    if a is None:
        return False
    if b is None:
        return True
    return tv(a) > tv(b)


# ---- state layout -------------------------------------------------------
# vne = (status, h, val, jts, pj, cj, proposed, rsent, completed, pending, tout, lout)
# pn  = (mode, vne, tobbuf, seqc, cnseen, sentnow)
# state = (pns, lb, M, F, ghost)
# lb entry = (ts, sender, msg, pending_receivers, obliged_receivers)
# ghost = (ledger, ledger2, sentmids, tc, gprev, lastval, wr)

VNE0 = ('active', None, START, None, None, None, False, False, frozenset(), (), (), ())
PN0 = ('A', VNE0, (), 0, frozenset(), False)
VNE_WARM = ('active', 0, START, None, None, None, False, False, frozenset(), (), (), ())

stats = {}


def rec(key, val):
    if val > stats.get(key, -1):
        stats[key] = val


def count(key):
    stats[key] = stats.get(key, 0) + 1


def setpn(pns, i, pn):
    l = list(pns)
    l[i] = pn
    return tuple(l)


def setvne(pn, vne):
    return (pn[0], vne, pn[2], pn[3], pn[4], pn[5])


def alive(pns, lb):
    """Holder predicate (spec D-alive): an active VNE, or a listening VNE with an
    adoptable join-ack in its TOBcast buffer or in flight to it."""
    for p in pns:
        if p[0] == 'A' and p[1][0] == 'active' and p[1][1] == 0:
            return True
    for j, p in enumerate(pns):
        if p[0] == 'A' and p[1][0] == 'listening':
            jts = p[1][3]
            for e in p[2]:
                pl = e[4]
                if pl[0] == 'jack' and tv(pl[2]) >= tv(jts):
                    return True
            for e in lb:
                m = e[2]
                if m[0] == 'tob' and j in e[3] and m[5][0] == 'jack' and tv(m[5][2]) >= tv(jts):
                    return True
    return False


def actives(pns):
    return [p[1] for p in pns if p[0] == 'A' and p[1][0] == 'active' and p[1][1] == 0]


def post(s):
    """Ghost bookkeeping after every discrete step."""
    pns, lb, M, F, g = s
    ledger, ledger2, sentmids, tc, gprev, lastval, wr, alprev = g
    al = alive(pns, lb)
    act = actives(pns)
    if act:
        best = min(act, key=lambda v: len(v[9]))
        lastval = best[2]
    elif not al:
        lastval = None
    if not al:
        ledger = frozenset()        # VN not alive: no obligation left (D-oblige)
    lb = tuple(sorted(lb, key=repr))   # canonical order of in-flight messages
    return (pns, lb, M, F, (ledger, ledger2, sentmids, tc, gprev, lastval, wr, alprev))


def lb_send(s, i, msg):
    pns, lb, M, F, g = s
    rcv = frozenset(j for j, p in enumerate(pns) if p[0] == 'A')   # includes the sender (distance 0)
    lb = lb + ((T(0), i, msg, rcv, rcv),)
    return (pns, lb, M, F, g)


def tob_insert(buf, entry):
    l = list(buf) + [entry]
    l.sort(key=lambda e: (tv(e[0]), e[1], e[2], e[3]))
    return tuple(l)


def deliver_lb(s, k, j):
    pns, lb, M, F, g = s
    ts, snd, msg, pend, obl = lb[k]
    pend2 = pend - {j}
    lb = lb[:k] + (((ts, snd, msg, pend2, obl),) if pend2 else ()) + lb[k + 1:]
    p = pns[j]
    ledger, ledger2, sentmids, tc, gprev, lastval, wr, alprev = g
    if p[0] != 'A':
        return (pns, lb, M, F, g)
    mode, vne, buf, seqc, cnseen, sentnow = p
    if msg[0] == 'tob':
        _, zone, sender, seq, mts, payload = msg
        if zone == 0:  # TOBcast_{j,h} processes only messages tagged for its zone (002:348)
            jord = 1 if payload[0] == 'jreq' else 0
            buf = tob_insert(buf, (mts, jord, sender, seq, payload))
    elif msg[0] == 'vn':
        _, zone, mid, body = msg
        if mid not in cnseen:          # trivial client: dedup (D-dup)
            cnseen = cnseen | {mid}
            new2 = set()
            for (m2, fts, obls) in ledger2:
                if m2 == mid and j in obls:
                    rec('lat VN->CN (from first physical send)', -tv(fts))
                    obls = obls - {j}
                if obls:
                    new2.add((m2, fts, obls))
            ledger2 = frozenset(new2)
        # own zone's VN message: the VNE ignores it (D-self)
    elif msg[0] == 'cn':
        _, zone, mid, body = msg
        if vne[1] == zone:
            act = ('recv', mid, mid[1])
            vne = vne[:10] + (vne[10] + (('sim', act, None),),) + vne[11:]
    p = (mode, vne, buf, seqc, cnseen, sentnow)
    pns = setpn(pns, j, p)
    return (pns, lb, M, F, (ledger, ledger2, sentmids, tc, gprev, lastval, wr, alprev))


def tob_rcv(s, i):
    """TOBcast-rcv(<optype,param,oid>)_{i,h}, 002:456, reconstructed (spec §1.4)."""
    pns, lb, M, F, g = s
    mode, vne, buf, seqc, cnseen, sentnow = pns[i]
    e = buf[0]
    buf = buf[1:]
    pl = e[4]
    st, h, val, jts, pj, cj, prop, rsent, comp, pend, tout, lout = vne
    if pl[0] == 'sim':
        if st in ('listening', 'active'):
            pend = pend + ((pl[1], pl[2]),)
    elif pl[0] == 'jreq':
        pj = tmax(pj, pl[1])
        if st == 'joining' and pl[1] == jts:
            st = 'listening'                       # D: the lost line
    elif pl[0] == 'jack':
        cj = tmax(cj, pl[2])
        if st == 'listening' and tv(pl[2]) >= tv(jts):
            st = 'active'
            val, comp = pl[1]
            prop = False
    elif pl[0] == 'reset':
        if g[7] and alive(pns, lb):
            count('spurious reset: VN alive at previous tick state and now')
        st = 'active'
        pend = ()
        if A.reset_val:
            val = START
            comp = frozenset()
        prop = False
    vne = (st, h, val, jts, pj, cj, prop, rsent, comp, pend, tout, lout)
    pns = setpn(pns, i, (mode, vne, buf, seqc, cnseen, sentnow))
    return (pns, lb, M, F, g)


def simulate(s, i):
    pns, lb, M, F, g = s
    mode, vne, buf, seqc, cnseen, sentnow = pns[i]
    st, h, val, jts, pj, cj, prop, rsent, comp, pend, tout, lout = vne
    act, oid = pend[0]
    pend = pend[1:]
    key = (act, oid)
    ledger = g[0]
    if key not in comp and vn_delta(val, act) is not None:
        val = vn_delta(val, act)
        prop = False
        if act[0] == 'send':
            lout = lout + (('vn', 0, oid, act[1]),)
        if act[0] == 'recv':
            mid = act[1]
            for (m2, ob) in ledger:
                if m2 == mid:
                    rec('lat CN->VN (first execution)', -tv(mid[0]))
                    ledger = ledger - {(m2, ob)}
        comp = comp | {key}
    elif A.record == 'always':
        comp = comp | {key}
    vne = (st, h, val, jts, pj, cj, prop, rsent, comp, pend, tout, lout)
    pns = setpn(pns, i, (mode, vne, buf, seqc, cnseen, sentnow))
    return (pns, lb, M, F, (ledger,) + g[1:])


def successors(s):
    """Yield (label, state, urgent).  Ticks are added by the caller."""
    pns, lb, M, F, g = s
    out = []
    for i, p in enumerate(pns):
        mode, vne, buf, seqc, cnseen, sentnow = p
        if mode == 'A':
            st, h, val, jts, pj, cj, prop, rsent, comp, pend, tout, lout = vne
            # zone-update (002:436-444)
            if h != 0:
                v2 = ('idle', 0, START, None, pj, cj, False, False, frozenset(), (), tout, lout)
                out.append((f'zone-update_{i}', (setpn(pns, i, setvne(p, v2)), lb, M, F, g), True))
            else:
                if st == 'idle':   # join (002:426-428)
                    v2 = ('joining', h, val, T(0), pj, cj, prop, False, comp, pend,
                          tout + ((('jreq', T(0))),), lout)
                    out.append((f'join_{i}', (setpn(pns, i, setvne(p, v2)), lb, M, F, g), True))
                if st == 'listening' and jts is not None and tv(jts) == -JOINWAIT and not rsent:
                    v2 = (st, h, val, jts, pj, cj, prop, True, comp, pend, tout + (('reset',),), lout)
                    out.append((f'restart_{i}', (setpn(pns, i, setvne(p, v2)), lb, M, F, g), True))
                if st == 'active':
                    act = vn_enabled(val)
                    if act is not None and not prop:   # init-action + D-proposed
                        v2 = (st, h, val, jts, pj, cj, True, rsent, comp, pend,
                              tout + (('sim', act, (T(0), i)),), lout)
                        out.append((f'init-action_{i}', (setpn(pns, i, setvne(p, v2)), lb, M, F, g), True))
                    if pend:
                        out.append((f'simulate_{i}', simulate(s, i), True))
                    quiet = (not A.quiescent_ack) or vn_enabled(val) is None
                    if tgt(pj, cj) and not pend and quiet:   # ack-join (002:456)
                        v2 = (st, h, val, jts, pj, tmax(cj, pj), prop, rsent, comp, pend,
                              tout + (('jack', (val, comp), pj),), lout)
                        out.append((f'ack-join_{i}', (setpn(pns, i, setvne(p, v2)), lb, M, F, g), True))
            if tout:   # TOBcast(m)_{i,h} output -> LBcast send (TOBcast automaton, spec §1.3)
                pl = tout[0]
                v2 = vne[:10] + (tout[1:],) + vne[11:]
                p2 = (mode, v2, buf, seqc + 1, cnseen, sentnow)
                s2 = (setpn(pns, i, p2), lb, M, F, g)
                s2 = lb_send(s2, i, ('tob', 0, i, seqc, T(0), pl))
                out.append((f'TOBcast_{i}', s2, True))
            if lout:   # send(m)_{i,h} output (002:416-418)
                m = lout[0]
                v2 = vne[:11] + (lout[1:],)
                s2 = (setpn(pns, i, setvne(p, v2)), lb, M, F, g)
                ledger, ledger2, sentmids, tc, gprev, lastval, wr, alprev = g
                if m[2] not in sentmids:   # first physical send = abstract VN send (D-abs-send)
                    obl = frozenset(j for j, q in enumerate(pns) if q[0] == 'A')
                    sentmids = sentmids | {m[2]}
                    if obl:
                        ledger2 = ledger2 | {(m[2], T(0), obl)}
                s2 = (s2[0], s2[1], M, F, (ledger, ledger2, sentmids, tc, gprev, lastval, wr, alprev))
                s2 = lb_send(s2, i, m)
                out.append((f'send_{i}', s2, True))
            if buf and tv(buf[0][0]) <= -TOBD:
                out.append((f'TOBcast-rcv_{i}', tob_rcv(s, i), True))
            # client: send an inc (environment, not urgent)
            if M > 0 and not sentnow:
                mid = (T(0), i)
                p2 = (mode, vne, buf, seqc, cnseen, True)
                s2 = (setpn(pns, i, p2), lb, M - 1, F, g)
                s2 = lb_send(s2, i, ('cn', 0, mid, 'inc'))
                if alive(pns, lb):
                    led = s2[4][0] | {(mid, True)}
                    s2 = s2[:4] + ((led,) + s2[4][1:],)
                out.append((f'cn-send_{i}', s2, False))
            if F > 0:   # fail_i: internal variables to initial values (002:35)
                lb2 = tuple((e[0], e[1], e[2], e[3] - {i}, e[4] - {i}) for e in lb)
                lb2 = tuple(e for e in lb2 if e[3])
                ledger, ledger2, sentmids, tc, gprev, lastval, wr, alprev = g
                ledger2 = frozenset((m, f, o - {i}) for m, f, o in ledger2 if o - {i})
                wr2 = wr[:i] + (0,) + wr[i + 1:]
                p2 = ('I', VNE0, (), 0, frozenset(), False)
                out.append((f'fail_{i}', (setpn(pns, i, p2), lb2, M, F - 1,
                                          (ledger, ledger2, sentmids, tc, gprev, lastval, wr2, alprev)), False))
        else:
            p2 = ('A',) + p[1:]
            out.append((f'recover_{i}', (setpn(pns, i, p2), lb, M, F, g), False))
    # LBcast deliveries: urgent for an obliged receiver at age DP
    for k, e in enumerate(lb):
        for j in sorted(e[3]):
            urgent = (tv(e[0]) <= -DP) and (j in e[4])
            out.append((f'lb-rcv_{j}', deliver_lb(s, k, j), urgent))
    res = [(lab, post(s2), u) for lab, s2, u in out]
    if A.env_at_ticks and any(u for _, _, u in res):
        res = [r for r in res if not r[0].startswith(('fail', 'recover', 'cn-send'))]
    if A.por and any(u for _, _, u in res):
        owner = lambda lab: int(lab.rsplit('_', 1)[1])
        k = min(owner(l) for l, _, u in res if u)
        res = [r for r in res if owner(r[0]) == k]
    return res


def tick(s):
    pns, lb, M, F, g = s
    ledger, ledger2, sentmids, tc, gprev, lastval, wr, alprev = g
    al = alive(pns, lb)
    act = actives(pns)
    # replica consistency at a time-passing state (spec P1)
    vals = {v[2] for v in act}
    if len(vals) > 1:
        count('P1 violated: active replicas differ at a tick state')
    for v in act:
        if v[9]:
            count('active replica with non-empty pending at tick')
    # MMT task clock (spec P3a)
    a = act[0][2] if act else (lastval if al else None)
    if a is None:
        tc, gprev = 0, None
    else:
        d, q = vn_enabled(a) is not None, a[3]
        if d:
            tc = (tc if gprev == (True, q) else 0) + 1
        else:
            tc = 0
        gprev = (d, q)
    rec('d_MMT measured (task clock)', tc)
    # d_r clocks (spec P3b)
    wr = tuple((w + 1) if (pns[i][0] == 'A' and not al) else 0 for i, w in enumerate(wr))
    for w in wr:
        rec('d_r measured (occupied & failed)', w)
    # obligations that expire
    for (m, ob) in ledger:
        if ob and -tv(m[0]) + 1 > DV:
            count('d_v CN->VN exceeded')
            rec('d_v CN->VN exceeded by (age)', -tv(m[0]) + 1)
    for (m, fts, ob) in ledger2:
        if ob and -tv(fts) + 1 > DV:
            count('d_v VN->CN exceeded')
    # age everything
    pns2 = []
    for p in pns:
        mode, vne, buf, seqc, cnseen, sentnow = p
        vne = age(vne)
        comp = frozenset(k for k in vne[8] if not any(isinstance(x, tuple) and x and x[0] == 't' and tv(x) < -H
                                                    for x in _times(k)))
        vne = vne[:8] + (comp,) + vne[9:]
        cnseen = frozenset(m for m in age(cnseen) if tv(m[0]) >= -H)
        pns2.append((mode, vne, age(buf), 0, cnseen, False))
    lb2 = []
    for e in lb:
        e2 = age(e)
        if tv(e2[0]) >= -DP:
            lb2.append(e2)
        else:
            assert not (e[3] & e[4]), 'obliged LB delivery missed'
    ledger = frozenset((m, ob) for (m, ob) in age(ledger) if -tv(m[0]) <= DV + 1)
    ledger2 = frozenset(x for x in age(ledger2) if -tv(x[1]) <= DV + 1)
    sentmids = frozenset(m for m in age(sentmids) if tv(m[0]) >= -H)
    return (tuple(pns2), tuple(lb2), M, F, (ledger, ledger2, sentmids, tc, gprev, age(lastval), wr, al))


def _times(x):
    if isinstance(x, tuple):
        if len(x) == 2 and x[0] == 't':
            yield x
        else:
            for y in x:
                yield from _times(y)


def main():
    vne0 = VNE_WARM if A.start == 'warm' else VNE0
    pn0 = ('A', vne0, (), 0, frozenset(), False)
    s0 = (tuple(pn0 for _ in range(N)), (), A.M, A.F,
          (frozenset(), frozenset(), frozenset(), 0, None, None, tuple(0 for _ in range(N)),
           A.start == 'warm'))
    seen = {s0}
    q = deque([s0])
    edges = 0
    ticks = 0
    timelocks = 0
    while q:
        s = q.popleft()
        succ = successors(s)
        urgent = any(u for _, _, u in succ)
        nxt = [s2 for _, s2, _ in succ]
        if not urgent:
            nxt.append(tick(s))
            ticks += 1
        if not nxt:
            timelocks += 1
        for s2 in nxt:
            edges += 1
            if s2 not in seen:
                seen.add(s2)
                q.append(s2)
        if len(seen) > A.max_states:
            print('INCOMPLETE: state limit')
            break
    print(f'params N={N} dp={DP} eps={EPS} M={A.M} F={A.F} K={A.K} S={A.S} start={A.start} '
          f'record={A.record} quiescent_ack={A.quiescent_ack} reset_val={A.reset_val}')
    print(f'paper: d_MMT={DMMT} d_r={DR} d_v={DV}')
    print(f'states={len(seen)} edges={edges} tick-states={ticks} timelocks={timelocks}')
    for k in sorted(stats):
        print(f'  {k}: {stats[k]}')


if __name__ == "__main__" and not globals().get("NO_MAIN"):
    main()
