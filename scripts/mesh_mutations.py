#!/usr/bin/python3
# A probe of the mesh import: N mutated copies of assimp's OBJ/STL/PLY/OFF test models (byte flips,
# cuts, inserted digits, truncation) through `tumble info`; counts how each ends. Any
# ending but exit 0 or 2 (a signal, a hang past 90 s, "internal error") is kept in
# build/mesh_mutations/. Usage: scripts/mesh_mutations.py N [SEED] [TUMBLE]
import random, subprocess, os, glob, sys, tempfile, time
random.seed(int(sys.argv[2]) if len(sys.argv) > 2 else 27)
T = sys.argv[3] if len(sys.argv) > 3 else 'build/release/src/app/tumble'
seeds = glob.glob('/usr/share/assimp/models/PLY/*.ply') + glob.glob('/usr/share/assimp/models/STL/*.stl') + \
        glob.glob('/usr/share/assimp/models/OBJ/*.obj') + glob.glob('/usr/share/assimp/models/OFF/*.off')
seeds = [s for s in seeds if os.path.getsize(s) < 200000]
work = tempfile.mkdtemp(prefix='tumble_mesh_mut_'); os.makedirs('build/mesh_mutations', exist_ok=True)
n = int(sys.argv[1]); stats = {}; t0 = time.time()
for i in range(n):
    s = random.choice(seeds)
    b = bytearray(open(s, 'rb').read())
    for _ in range(random.randint(1, 8)):
        op = random.random()
        if op < 0.4 and b: b[random.randrange(len(b))] = random.randrange(256)
        elif op < 0.6 and b:
            k = random.randrange(len(b)); del b[k:k+random.randint(1, 64)]
        elif op < 0.8:
            k = random.randrange(len(b)+1); b[k:k] = bytes(random.choice(b'0123456789 -.\n') for _ in range(random.randint(1,8)))
        else: b = b[:random.randrange(len(b)+1)]
    ext = os.path.splitext(s)[1].lower()
    open(f'{work}/cur{ext}', 'wb').write(b)
    open(f'{work}/cur.toml', 'w').write(f'[[bodies]]\nshape = {{ type = "mesh", file = "cur{ext}", resolution = 10 }}\n')
    try:
        r = subprocess.run([T, 'info', f'{work}/cur.toml'], capture_output=True, timeout=90)
        kind = f'exit{r.returncode}' if r.returncode >= 0 else f'sig{-r.returncode}'
        if b'internal error' in r.stderr: kind = 'internal'
    except subprocess.TimeoutExpired:
        kind = 'hang'
    stats[kind] = stats.get(kind, 0) + 1
    if kind not in ('exit0', 'exit2'): open(f'build/mesh_mutations/{kind}_{i}{ext}', 'wb').write(b)
print(stats, f'{time.time()-t0:.0f} s')
