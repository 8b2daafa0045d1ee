#!/usr/bin/python3
"""Meshes that real users bring, for checking issue 18's claim (tone across a 16-fold range of size) beyond
the shared models: arrow-glyph fields, marching-tetrahedra isosurfaces (gyroid, metaballs), a terrain, a
CAD-like plate, a sphere tessellated 100x finer on one side, a helix tube, random boxes, flat low-poly balls,
a sphere with its faces sorted by normal, a cloud of 100,000 tetrahedra turned about one axis. Written by a helper's survey of 2026-12-05 (docs/paper-reading.md,
"What ink means on screen"). Needs python3 with numpy; not part of the build or the tests.

Usage: tools/tone_survey_meshes.py [g01 g02 g03 g03b g04 ... g11 g11s]   those meshes (default all) in $SURVEY_DIR
       tools/tone_survey_meshes.py variants   the variants (shuffled faces, thicker arrows, fewer boxes), with
                                              the meshes two are made from (g01, g03b)
SURVEY_DIR defaults to ./tone-survey-meshes. Then, for each mesh:
  stipple tone MESH.obj --seeds 1,2,3 --fov 4 --frames 16 --arc 360 --views 30:10,30:-15 --regimes
"""
import numpy as np, sys, os
OUT = os.environ.get("SURVEY_DIR", "tone-survey-meshes")
os.makedirs(OUT, exist_ok=True)

def write_obj(name, V, F):
    V = np.asarray(V, float); F = np.asarray(F, int)
    with open(os.path.join(OUT, name + ".obj"), "w") as f:
        f.write("# %s\n" % name)
        f.write("".join("v %.6f %.6f %.6f\n" % tuple(v) for v in V))
        f.write("".join("f %d %d %d\n" % (a+1, b+1, c+1) for a, b, c in F))
    print(name, len(V), "verts", len(F), "tris")

def merge(parts):
    Vs, Fs, off = [], [], 0
    for V, F in parts:
        Vs.append(V); Fs.append(F + off); off += len(V)
    return np.vstack(Vs), np.vstack(Fs)

def arrow(n=7):
    """closed arrow along +z: bottom cap, cylinder, annulus, cone; 6n faces (n=7 -> 42)"""
    a = np.linspace(0, 2*np.pi, n, endpoint=False)
    c, s = np.cos(a), np.sin(a)
    r, R, h = 0.06, 0.15, 0.65
    V = [[0, 0, 0]] + [[r*c[i], r*s[i], 0] for i in range(n)] + [[r*c[i], r*s[i], h] for i in range(n)] \
        + [[R*c[i], R*s[i], h] for i in range(n)] + [[0, 0, 1.0]]
    V = np.array(V); F = []
    for i in range(n):
        j = (i+1) % n
        F.append([0, 1+j, 1+i])                                      # bottom cap
        F.append([1+i, 1+j, 1+n+j]); F.append([1+i, 1+n+j, 1+n+i])   # cylinder
        F.append([1+n+i, 1+n+j, 1+2*n+j]); F.append([1+n+i, 1+2*n+j, 1+2*n+i])  # annulus
        F.append([1+2*n+i, 1+2*n+j, 1+3*n])                          # cone
    return V, orient_out(V, np.array(F), np.array([0, 0, 0.7]))

def orient_out(V, F, centre):
    """flip faces so that the normal points away from centre (star-shaped parts)"""
    F = F.copy(); C = V[F].mean(1); N = np.cross(V[F[:,1]]-V[F[:,0]], V[F[:,2]]-V[F[:,0]])
    flip = (N*(C-centre)).sum(1) < 0; F[flip] = F[flip][:, ::-1]; return F

def rot_to(d):
    d = d/np.linalg.norm(d); z = np.array([0, 0, 1.0])
    v = np.cross(z, d); c = d @ z
    if np.linalg.norm(v) < 1e-9:
        return np.eye(3) if c > 0 else np.diag([1, -1, -1.0])
    K = np.array([[0, -v[2], v[1]], [v[2], 0, -v[0]], [-v[1], v[0], 0]])
    return np.eye(3) + K + K@K*(1/(1+c))

def glyph_field(name, direction_fn, nx=60, ny=60):
    Va, Fa = arrow(7)
    parts = []
    for i in range(nx):
        for j in range(ny):
            p = np.array([i, j, 0.0])
            R = rot_to(direction_fn(i/nx, j/ny))
            parts.append(((Va*1.2) @ R.T + p, Fa))
    V, F = merge(parts); write_obj(name, V, F)

def g01(): glyph_field("01_arrows_uniform", lambda u, v: np.array([1.0, 0.3, 0.2]))
def g02(): glyph_field("02_arrows_field", lambda u, v: np.array([np.cos(4*v+2*u)*np.cos(3*u), np.sin(4*v+2*u)*np.cos(3*u), np.sin(3*u)]))

def marching_tets(f, lo, hi, n):
    xs = np.linspace(lo, hi, n+1)
    X, Y, Z = np.meshgrid(xs, xs, xs, indexing="ij")
    val = f(X, Y, Z)
    cube = np.array([[0,0,0],[1,0,0],[1,1,0],[0,1,0],[0,0,1],[1,0,1],[1,1,1],[0,1,1]])
    tets = [[0,5,1,6],[0,1,2,6],[0,2,3,6],[0,3,7,6],[0,7,4,6],[0,4,5,6]]
    V, F = [], []; cache = {}
    def ev(a, b):
        key = (min(a, b), max(a, b))
        if key in cache: return cache[key]
        va, vb = val[a], val[b]; t = va/(va-vb)
        pa = np.array([xs[a[0]], xs[a[1]], xs[a[2]]]); pb = np.array([xs[b[0]], xs[b[1]], xs[b[2]]])
        V.append(pa + t*(pb-pa)); cache[key] = len(V)-1; return cache[key]
    inside = val < 0
    # only cells with a sign change
    anyin = np.zeros((n, n, n), bool); allin = np.ones((n, n, n), bool)
    for c in cube:
        s = inside[c[0]:c[0]+n, c[1]:c[1]+n, c[2]:c[2]+n]; anyin |= s; allin &= s
    for (i, j, k) in np.argwhere(anyin & ~allin):
        corners = [tuple(np.array([i, j, k]) + c) for c in cube]
        for t in tets:
            p = [corners[q] for q in t]
            ins = [inside[q] for q in p]
            I = [q for q, b in zip(p, ins) if b]; O = [q for q, b in zip(p, ins) if not b]
            if len(I) == 0 or len(I) == 4: continue
            if len(I) == 1:
                tri = [ev(I[0], o) for o in O]
                F.append(tri)
            elif len(I) == 3:
                tri = [ev(i_, O[0]) for i_ in I]
                F.append(tri)
            else:
                a, b, c_, d = ev(I[0], O[0]), ev(I[0], O[1]), ev(I[1], O[1]), ev(I[1], O[0])
                F.append([a, b, c_]); F.append([a, c_, d])
    V = np.array(V); F = np.array(F)
    # orient each face so its normal follows the gradient (outward: f increases)
    C = V[F].mean(1); N = np.cross(V[F[:,1]]-V[F[:,0]], V[F[:,2]]-V[F[:,0]])
    e = 1e-3; g = np.stack([(f(C[:,0]+e, C[:,1], C[:,2])-f(C[:,0]-e, C[:,1], C[:,2])),
                            (f(C[:,0], C[:,1]+e, C[:,2])-f(C[:,0], C[:,1]-e, C[:,2])),
                            (f(C[:,0], C[:,1], C[:,2]+e)-f(C[:,0], C[:,1], C[:,2]-e))], 1)
    flip = (N*g).sum(1) < 0; F[flip] = F[flip][:, ::-1]
    return V, F

def g03():
    def gyroid(x, y, z):
        return np.sin(x)*np.cos(y) + np.sin(y)*np.cos(z) + np.sin(z)*np.cos(x)
    # gyroid clipped to a sphere: max(gyroid, |p|-R)
    def f(x, y, z): return np.maximum(gyroid(x, y, z), np.sqrt(x*x+y*y+z*z) - 6.0)
    V, F = marching_tets(f, -6.3, 6.3, 48); write_obj("03_gyroid_mt", V, F)

def g03b():
    cs = np.array([[0,0,0],[1.1,0.2,0],[-0.6,0.9,0.3],[0.2,-0.8,0.7],[0.3,0.3,-0.9]])
    def f(x, y, z):
        s = 0
        for c in cs: s = s + 1.0/((x-c[0])**2+(y-c[1])**2+(z-c[2])**2+1e-6)
        return 1.6 - s
    V, F = marching_tets(f, -2.2, 2.4, 44); write_obj("03b_metaballs_mt", V, F)

def fractal_noise(n, rng, octaves=6):
    h = np.zeros((n, n))
    for o in range(octaves):
        k = 2**(o+2); g = rng.standard_normal((k+1, k+1))
        xs = np.linspace(0, k, n); i = np.minimum(xs.astype(int), k-1); t = xs - i
        t = t*t*(3-2*t)
        a = g[i][:, i]*(1-t)[None]+g[i][:, i+1]*t[None]; b = g[i+1][:, i]*(1-t)[None]+g[i+1][:, i+1]*t[None]
        h += (a*(1-t)[:, None]+b*t[:, None]) / 2**o
    return h

def g04():
    n = 300; rng = np.random.default_rng(4)
    h = fractal_noise(n, rng) * 12
    xs = np.arange(n, dtype=float)
    X, Y = np.meshgrid(xs, xs, indexing="ij")
    V = np.stack([X.ravel(), Y.ravel(), h.ravel()], 1)
    idx = np.arange(n*n).reshape(n, n)
    a = idx[:-1, :-1].ravel(); b = idx[1:, :-1].ravel(); c = idx[1:, 1:].ravel(); d = idx[:-1, 1:].ravel()
    F = np.vstack([np.stack([a, b, c], 1), np.stack([a, c, d], 1)])
    # OBJ is y-up conventionally; user "views as is (z up)": keep z up in the file
    write_obj("04_terrain", V, F)

def g05():
    """plate 100x60x8 with 12 round holes; top/bottom faces fan-triangulated from a single vertex per
    region (long slivers), hole walls and filleted top edges as thin strips"""
    W, H, T = 100.0, 60.0, 8.0; fr = 1.0; seg = 48
    holes = [(12.5+25*i, 10+20*j, 4.0 if (i+j) % 2 else 2.5) for i in range(4) for j in range(3)]
    V = []; F = []
    def add(p): V.append(p); return len(V)-1
    # top & bottom: for each hole, the plate is partitioned into cells; simpler: fan from plate corner
    # into the ring of each hole isn't planar-valid. Use: cells 25x20 around each hole, each cell's
    # square boundary fanned to the hole ring (CAD-like fans).
    cw, ch = W/4, H/3
    for z, up in ((T, True), (0.0, False)):
        for (cx, cy, r) in holes:
            i = int((cx-0)//cw); j = int((cy-0)//ch)
            x0, y0 = i*cw, j*ch
            sq = [(x0, y0), (x0+cw, y0), (x0+cw, y0+ch), (x0, y0+ch)]
            rr = r + fr if up else r
            ring = [add([cx+rr*np.cos(t), cy+rr*np.sin(t), z]) for t in np.linspace(0, 2*np.pi, seg, endpoint=False)]
            sqi = [add([x, y, z]) for x, y in sq]
            # CAD-style fans: each cell corner fans to the hole ring arc facing it, plus one triangle per
            # cell edge (corner, next corner, ring vertex facing the edge's middle)
            ring_ang = np.linspace(0, 2*np.pi, seg, endpoint=False)
            bq = []
            for q in range(4):
                m = (np.array(sq[q]) + np.array(sq[(q+1) % 4]))/2
                am = np.arctan2(m[1]-cy, m[0]-cx) % (2*np.pi)
                bq.append(int(np.argmin(np.abs(np.angle(np.exp(1j*(ring_ang-am)))))))
            for q in range(4):
                k = bq[q-1]
                while k != bq[q]:
                    F.append([sqi[q], ring[k], ring[(k+1) % seg]]); k = (k+1) % seg
                F.append([sqi[q], sqi[(q+1) % 4], ring[bq[q]]])
            # facing: top +z, bottom -z
            for t in range(len(F)-seg-4, len(F)):
                p = np.array([V[i] for i in F[t]]); nz = np.cross(p[1]-p[0], p[2]-p[0])[2]
                if (nz > 0) != up: F[t] = F[t][::-1]
    # hole walls and fillet strips
    for (cx, cy, r) in holes:
        prof = [(r, 0.0), (r, T-fr)] + [(r+fr-fr*np.cos(a), T-fr+fr*np.sin(a)) for a in np.linspace(0, np.pi/2, 6)[1:]]
        rings = []
        for (rad, z) in prof:
            rings.append([add([cx+rad*np.cos(t), cy+rad*np.sin(t), z]) for t in np.linspace(0, 2*np.pi, seg, endpoint=False)])
        for a_, b_ in zip(rings[:-1], rings[1:]):
            for k in range(seg):
                k1 = (k+1) % seg
                F.append([a_[k], b_[k1], a_[k1]]); F.append([a_[k], b_[k], b_[k1]])
    # outer sides (with small fillet strips on the top edges: 6 strips each)
    box = [(0, 0), (W, 0), (W, H), (0, H)]
    for q in range(4):
        p0 = np.array(box[q]); p1 = np.array(box[(q+1) % 4]); e = p1-p0; nrm = np.array([e[1], -e[0]])/np.linalg.norm(e)
        prof = [(0.0, 0.0), (0.0, T-fr)] + [(-fr+fr*np.cos(a), T-fr+fr*np.sin(a)) for a in np.linspace(0, np.pi/2, 6)[1:]]
        rows = []
        for (off, z) in prof:
            rows.append([add([*(p0+nrm*off), z]), add([*(p1+nrm*off), z])])
        for a_, b_ in zip(rows[:-1], rows[1:]):
            F.append([a_[0], a_[1], b_[1]]); F.append([a_[0], b_[1], b_[0]])
    V = np.array(V); F = np.array(F)
    # repeat plate 6x in a 3x2 arrangement to reach the 5k-triangle floor
    parts = [(V + [i*110, j*70, 0], F) for i in range(3) for j in range(2)]
    V, F = merge(parts)
    write_obj("05_cad_plate", V, F)

def uv_sphere_nonuniform():
    # latitude rings: north hemisphere fine (step d), south coarse (step 10d in angle => 100x area)
    Vs = []; F = []
    fine = np.linspace(0, np.pi/2, 201)  # theta from north pole to equator
    coarse = np.linspace(np.pi/2, np.pi, 21)
    thetas = np.concatenate([fine, coarse[1:]])
    nphi_f, nphi_c = 400, 40
    rings = []
    for t in thetas:
        nphi = nphi_f if t <= np.pi/2 + 1e-9 else nphi_c
        if t == 0 or abs(t-np.pi) < 1e-9: nphi = 1
        ph = np.linspace(0, 2*np.pi, nphi, endpoint=False)
        start = len(Vs)
        for p in ph: Vs.append([np.sin(t)*np.cos(p), np.sin(t)*np.sin(p), np.cos(t)])
        rings.append((start, nphi))
    def ring_strip(A, B):
        (sa, na), (sb, nb) = A, B
        i = j = 0
        while i < na or j < nb:
            if i < na and (j >= nb or (i+1)/na <= (j+1)/nb):
                F.append([sa+i % na, sb+j % nb, sa+(i+1) % na]); i += 1
            else:
                F.append([sa+i % na, sb+j % nb, sb+(j+1) % nb]); j += 1
    for a, b in zip(rings[:-1], rings[1:]): ring_strip(a, b)
    V = np.array(Vs); F = np.array(F)
    # fix orientation outward
    C = V[F].mean(1); N = np.cross(V[F[:,1]]-V[F[:,0]], V[F[:,2]]-V[F[:,0]])
    flip = (N*C).sum(1) < 0; F[flip] = F[flip][:, ::-1]
    # remove degenerate (pole fan duplicates)
    A = np.linalg.norm(np.cross(V[F[:,1]]-V[F[:,0]], V[F[:,2]]-V[F[:,0]]), axis=1)
    return V, F[A > 1e-12]

def g06():
    V, F = uv_sphere_nonuniform(); write_obj("06_sphere_nonuniform", V, F)

def helix_tube(name, turns, R, pitch, n, m):
    t = np.linspace(0, 2*np.pi*turns, n)
    P = np.stack([R*np.cos(t), R*np.sin(t), pitch/(2*np.pi)*t], 1)
    T = np.gradient(P, axis=0); T /= np.linalg.norm(T, axis=1)[:, None]
    Nn = np.stack([np.cos(t), np.sin(t), 0*t], 1)
    Nn -= (Nn*T).sum(1)[:, None]*T; Nn /= np.linalg.norm(Nn, axis=1)[:, None]
    B = np.cross(T, Nn)
    L = np.linalg.norm(np.diff(P, axis=0), axis=1).sum(); r = L/100  # diameter = L/50
    print(name, "centre-line length %.2f tube diameter %.3f pitch %.2f" % (L, 2*r, pitch))
    a = np.linspace(0, 2*np.pi, m, endpoint=False)
    V = (P[:, None] + r*(np.cos(a)[None, :, None]*Nn[:, None] + np.sin(a)[None, :, None]*B[:, None])).reshape(-1, 3)
    F = []
    for i in range(n-1):
        for k in range(m):
            k1 = (k+1) % m; a0 = i*m+k; a1 = i*m+k1; b0 = a0+m; b1 = a1+m
            F.append([a0, a1, b1]); F.append([a0, b1, b0])
    F = np.array(F)
    C = V[F].mean(1); idx = np.arange(len(F))//(2*m); axisp = P[idx]
    N = np.cross(V[F[:,1]]-V[F[:,0]], V[F[:,2]]-V[F[:,0]])
    flip = (N*(C-axisp)).sum(1) < 0; F[flip] = F[flip][:, ::-1]
    write_obj(name, V, F)

def g07():
    # 3 turns, radius 3, pitch 6: the tube (diameter = length/50 = 1.19) clears the next coil
    helix_tube("07_helix_tube", 3, 3.0, 6.0, 4000, 16)

def g07x():
    # the first attempt: 12 turns of pitch 2.51 with a tube of diameter 4.56, so the coils interpenetrate
    helix_tube("07x_helix_coils_intersecting", 12, 3.0, 0.4*2*np.pi, 4000, 16)

def box(c, s, R):
    v = np.array([[x, y, z] for x in (-1, 1) for y in (-1, 1) for z in (-1, 1)], float)*s/2
    F = np.array([[0,1,3],[0,3,2],[4,6,7],[4,7,5],[0,4,5],[0,5,1],[2,3,7],[2,7,6],[0,2,6],[0,6,4],[1,5,7],[1,7,3]])
    V = v @ R.T + c
    return V, orient_out(V, F, c)

def randrot(rng):
    q = rng.standard_normal(4); q /= np.linalg.norm(q); w, x, y, z = q
    return np.array([[1-2*(y*y+z*z), 2*(x*y-z*w), 2*(x*z+y*w)], [2*(x*y+z*w), 1-2*(x*x+z*z), 2*(y*z-x*w)], [2*(x*z-y*w), 2*(y*z+x*w), 1-2*(x*x+y*y)]])

def g08(nbox=1500, name="08_random_boxes"):
    rng = np.random.default_rng(8); parts = []
    for i in range(nbox):
        s = 10**rng.uniform(-1, 1)*np.array([1, rng.uniform(0.5, 1.5), rng.uniform(0.5, 1.5)])  # sizes 0.1..10: 100x
        c = rng.uniform(-40, 40, 3)
        parts.append(box(c, s, randrot(rng)))
    V, F = merge(parts)
    # fix orientation: each box outward from its centre
    write_obj(name, V, F)

def icosphere(level):
    t = (1+5**0.5)/2
    V = [[-1,t,0],[1,t,0],[-1,-t,0],[1,-t,0],[0,-1,t],[0,1,t],[0,-1,-t],[0,1,-t],[t,0,-1],[t,0,1],[-t,0,-1],[-t,0,1]]
    F = [[0,11,5],[0,5,1],[0,1,7],[0,7,10],[0,10,11],[1,5,9],[5,11,4],[11,10,2],[10,7,6],[7,1,8],[3,9,4],[3,4,2],[3,2,6],[3,6,8],[3,8,9],[4,9,5],[2,4,11],[6,2,10],[8,6,7],[9,8,1]]
    V = [np.array(v, float)/np.linalg.norm(v) for v in V]
    for _ in range(level):
        mid = {}; NF = []
        def m(a, b):
            k = (min(a, b), max(a, b))
            if k not in mid:
                p = V[a]+V[b]; V.append(p/np.linalg.norm(p)); mid[k] = len(V)-1
            return mid[k]
        for a, b, c in F:
            ab, bc, ca = m(a, b), m(b, c), m(c, a)
            NF += [[a, ab, ca], [b, bc, ab], [c, ca, bc], [ab, bc, ca]]
        F = NF
    return np.array(V), np.array(F)

def g09():
    # low-poly flat-shaded: icosahedron subdivided once (80 faces), no shared vertices; 80 tris alone is
    # below the 5k floor, so a 10x8 field of 80-face balls of different sizes, each a flat low-poly object
    V1, F1 = icosphere(1)
    rng = np.random.default_rng(9); parts = []
    for i in range(10):
        for j in range(8):
            s = rng.uniform(0.6, 1.4); R = randrot(rng)
            V = (V1 @ R.T)*s + [3*i, 3*j, 0]
            Vf = V[F1].reshape(-1, 3); Ff = np.arange(len(Vf)).reshape(-1, 3)
            parts.append((Vf, Ff))
    V, F = merge(parts); write_obj("09_lowpoly_flat", V, F)

def g09b():
    V1, F1 = icosphere(1)
    Vf = V1[F1].reshape(-1, 3); Ff = np.arange(len(Vf)).reshape(-1, 3)
    write_obj("09b_lowpoly_single80", Vf, Ff)

def g10():
    V, F = icosphere(6)  # 81920 tris
    C = V[F].mean(1); C /= np.linalg.norm(C, axis=1)[:, None]
    # sort faces by normal direction: primary by quantised azimuth, then elevation (like a CAD exporter)
    order = np.lexsort((np.round(C[:, 2], 2), np.round(np.arctan2(C[:, 1], C[:, 0]), 1)))
    write_obj("10_sphere_sorted", V, F[order])

def g10_shuffled():
    V, F = icosphere(6); rng = np.random.default_rng(10)
    write_obj("10s_sphere_shuffled", V, F[rng.permutation(len(F))])

def g11():
    """100,000 regular tetrahedra (half-edge 0.01) in a ball of radius 1, each turned about z alone"""
    import random, math
    random.seed(5)
    with open(os.path.join(OUT, "11_tetrahedron_cloud.obj"), "w") as f:
        vi = 1
        for i in range(100000):
            while True:
                c = [random.uniform(-1, 1) for _ in range(3)]
                if sum(x*x for x in c) <= 1: break
            a = random.uniform(0, 2*math.pi); ca, sa = math.cos(a), math.sin(a)
            for x, y, z in [(1, 1, 1), (1, -1, -1), (-1, 1, -1), (-1, -1, 1)]:
                x, y = ca*x - sa*y, sa*x + ca*y
                f.write("v %.6f %.6f %.6f\n" % (c[0] + 0.01*x, c[1] + 0.01*y, c[2] + 0.01*z))
            f.write("f %d %d %d\nf %d %d %d\nf %d %d %d\nf %d %d %d\n" % (vi, vi+2, vi+1, vi, vi+1, vi+3, vi, vi+3, vi+2, vi+1, vi+2, vi+3))
            vi += 4
    print("11_tetrahedron_cloud 400000 verts 400000 tris")

def g11s():
    """the same kind of cloud (other places and angles), each copy's four faces in a random order"""
    import random, math
    random.seed(5); np.random.seed(5)
    pts = np.array([(1, 1, 1), (1, -1, -1), (-1, 1, -1), (-1, -1, 1)], float)
    with open(os.path.join(OUT, "11s_tetrahedron_cloud_shuffled.obj"), "w") as f:
        vi = 1
        for i in range(100000):
            while True:
                c = np.random.uniform(-1, 1, 3)
                if c @ c <= 1: break
            a = random.uniform(0, 2*math.pi); co, si = math.cos(a), math.sin(a)
            R = np.array([[co, -si, 0], [si, co, 0], [0, 0, 1]])
            for p in c + 0.01*(pts @ R.T): f.write("v %.6f %.6f %.6f\n" % tuple(p))
            faces = [(vi, vi+2, vi+1), (vi, vi+1, vi+3), (vi, vi+3, vi+2), (vi+1, vi+2, vi+3)]
            random.shuffle(faces)
            for fc in faces: f.write("f %d %d %d\n" % fc)
            vi += 4
    print("11s_tetrahedron_cloud_shuffled 400000 verts 400000 tris")

GENS = {k: v for k, v in globals().items() if k.startswith("g") and callable(v) and k[1:2].isdigit()}
if __name__ == "__main__" and "variants" not in sys.argv[1:]:
    names = sys.argv[1:] or sorted(GENS)
    unknown = [n for n in names if n not in GENS]
    if unknown:
        sys.exit("tone_survey_meshes.py: unknown mesh %s (known: %s, variants)" % (", ".join(unknown), " ".join(sorted(GENS))))
    for n in names: GENS[n]()

# ---- variants used to narrow down failures ----
def read_obj(name):
    V = []; F = []
    for l in open(os.path.join(OUT, name + ".obj")):
        if l[:2] == "v ": V.append(list(map(float, l.split()[1:4])))
        elif l[:2] == "f ": F.append([int(x)-1 for x in l.split()[1:4]])
    return np.array(V), np.array(F)

def shuffled(src, dst, seed):
    V, F = read_obj(src); rng = np.random.default_rng(seed)
    write_obj(dst, V, F[rng.permutation(len(F))])

def gv01s(): shuffled("01_arrows_uniform", "01s_arrows_uniform_shuffled", 101)
def gv03bs(): shuffled("03b_metaballs_mt", "03bs_metaballs_mt_shuffled", 103)

def gv01t():
    """the uniform arrow field with every glyph 3x thicker (shaft and head radius), same length and grid"""
    Va, Fa = arrow(7); Va = Va * [3, 3, 1]
    parts = []
    R = rot_to(np.array([1.0, 0.3, 0.2]))
    for i in range(60):
        for j in range(60):
            parts.append(((Va*1.2) @ R.T + [i, j, 0.0], Fa))
    V, F = merge(parts); write_obj("01t_arrows_uniform_thick", V, F)

def gv08sparse():
    """the same box distribution (sizes 0.1..10, same 80^3 volume) with 450 boxes instead of 1500: less overlap"""
    g08(450, "08v_random_boxes_sparse")

if __name__ == "__main__" and "variants" in sys.argv[1:]:
    for needed in ("g01", "g03b"):  # the shuffled variants are made from these
        GENS[needed]()
    for n in ("gv01s", "gv03bs", "gv01t", "gv08sparse"): globals()[n]()
