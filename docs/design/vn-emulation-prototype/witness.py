"""BFS with parents; print the shortest trace to the first step that bumps stats[KEY]
(or makes stats[KEY] exceed a value).  Usage: witness.py KEY [THRESH] -- <vn_proto args>"""
import sys
key = sys.argv[1]
thresh = None
rest = sys.argv[2:]
if rest and rest[0] != '--':
    thresh = int(rest[0]); rest = rest[1:]
assert rest[0] == '--'
sys.argv = ['vn_proto.py'] + rest[1:]
NO_MAIN = True
exec(open('vn_proto.py').read())
from collections import deque
vne0 = VNE_WARM if A.start == 'warm' else VNE0
pn0 = ('A', vne0, (), 0, frozenset(), False)
s0 = (tuple(pn0 for _ in range(N)), (), A.M, A.F,
      (frozenset(), frozenset(), frozenset(), 0, None, None, tuple(0 for _ in range(N)), A.start == 'warm'))
parent = {s0: None}
q = deque([s0])
def hit():
    v = stats.get(key)
    return v is not None and (thresh is None or v > thresh)
def show(path):
    t = 0
    for lab, s in path:
        if lab == 'tick':
            t += 1; print(f'--- tick -> time {t}'); continue
        pns, lb, M, F, g = s
        desc = []
        for i, p in enumerate(pns):
            v = p[1]
            desc.append(f'PN{i}:{p[0]}/{v[0]} val={v[2]} pend={len(v[9])} buf={[e[4][0] for e in p[2]]}')
        print(f't={t} {lab:22s} ' + ' | '.join(desc))
while q:
    s = q.popleft()
    succ = successors(s)
    urgent = any(u for _, _, u in succ)
    nxt0 = [(l, s2) for l, s2, _ in succ]
    if hit():
        path = []
        x = s
        while parent[x] is not None:
            px, l = parent[x]; path.append((l, x)); x = px
        path.reverse()
        show(path)
        print('== the hit is among the steps from the last state:', [l for l, _ in nxt0])
        break
    nxt = [(l, s2) for l, s2, _ in succ]
    if not urgent:
        before = dict(stats)
        nxt.append(('tick', tick(s)))
    for l, s2 in nxt:
        if s2 not in parent:
            parent[s2] = (s, l); q.append(s2)
    if hit():
        # find which successor: re-run successors to attribute is messy; print path to s, then the candidates
        path = []
        x = s
        while parent[x] is not None:
            px, l = parent[x]; path.append((l, x)); x = px
        path.reverse()
        show(path)
        print('== then, from the last state, one of:', [l for l, _ in nxt])
        break
