"""Exhaustive search restricted to a scripted environment: env steps (fail/recover/cn-send)
only at the times the script allows (everything else -- delivery timing, interleavings,
mid-burst placement of the allowed env steps -- stays nondeterministic).
Usage: scripted.py 'T:label,label;T:label' -- <vn_proto args>"""
import sys
script = {}
for part in sys.argv[1].split(';'):
    t, labs = part.split(':')
    script[int(t)] = set(labs.split(','))
rest = sys.argv[2:]
assert rest[0] == '--'
sys.argv = ['vn_proto.py'] + rest[1:]
NO_MAIN = True
exec(open('vn_proto.py').read())
from collections import deque
HOR = max(script) + 14
vne0 = VNE_WARM if A.start == 'warm' else VNE0
pn0 = ('A', vne0, (), 0, frozenset(), False)
s0 = (tuple(pn0 for _ in range(N)), (), A.M, A.F,
      (frozenset(), frozenset(), frozenset(), 0, None, None, tuple(0 for _ in range(N)), A.start == 'warm'))
seen = {(s0, 0)}
q = deque([(s0, 0)])
while q:
    s, t = q.popleft()
    succ = successors(s)
    urgent = any(u for _, _, u in succ)
    nxt = []
    for l, s2, u in succ:
        if l.startswith(('fail', 'recover', 'cn-send')) and l not in script.get(t, ()):
            continue
        nxt.append((s2, t))
    if not urgent and t < HOR:
        nxt.append((tick(s), t + 1))
    for x in nxt:
        if x not in seen:
            seen.add(x); q.append(x)
print('states', len(seen))
for k in sorted(stats):
    print(f'  {k}: {stats[k]}')
