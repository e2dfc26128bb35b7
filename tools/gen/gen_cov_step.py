#!/usr/bin/env python3
"""Writes src/cov/gen/cov_step_kernel.c, the per-sample covariance kernels of
cov_step.h as straight-line code: the covariance step for 9 states and for
15, and the three steps of a preintegrated factor's left form (its input
matrix, covariance and bias Jacobian).

  python3 tools/gen/gen_cov_step.py           write the file
  python3 tools/gen/gen_cov_step.py --check   exit 1 if it is not current

The algorithm is the block form of cov_step.h / cov_step.c's file comment
(shear G, input terms E, rotation D, by 3x3 blocks, upper triangles of the
symmetric blocks only). This script expands every block product into
scalar statements, skips the products with structural zeros (v^ and p^
have zero diagonals, Bt's phi row has no accel block, dt I is diagonal),
and counts the arithmetic it emits. Every entry of P is read once, into a
local, and each entry of out is stored once, after the read of the entry
it overwrites: out may alias P. The two 15-state bias stages, whose live
sets are the largest, instead read the entries of P they do not store, and
U, Bt, q and the scratch S, at every use: held in locals across the
stores to out, which the compiler must assume may change them, they were
spilled to the stack (frames of 440-472 B on Cortex-M4F, now 264-280 B).
"""
import os
import sys
import textwrap

HERE = os.path.dirname(os.path.abspath(__file__))
OUT = os.path.join(HERE, "..", "..", "src", "cov", "gen", "cov_step_kernel.c")


class Gen:
    """Emits the statements of one function. An entry of a 3x3 block is
    None (a structural zero) or (sign, name) of a scalar local."""

    def __init__(self, used=None, stored=None, src="P", dst="out", stride=None, prefix="p",
                 reread=False):
        self.src, self.dst, self.stride = src, dst, stride  # stride None: `stride`
        self.prefix = prefix  # of the locals read from src
        self.lines = []
        self.ntmp = 0
        self.muls = 0
        self.adds = 0
        self.loaded = set()
        self.used = used if used is not None else set()  # P entries read at all
        self.record = used is None
        self.stored = stored if stored is not None else set()  # P entries it stores
        self.reread = reread  # inputs and unstored P entries read at every use
        self.reads = set()
        self.pending = []  # (row, col, entry) stores not yet emitted
        self.lazy = []  # [emitted entry or None, base, products] per sum
        self.stores = 0
        self.inputs = {}  # name -> its read from U, Bt, q or S

    # --- loads of P, lazy ---------------------------------------------------
    def p_name(self, r, c):
        return "%s%d_%d" % (self.prefix, r, c)

    def load(self, r, c):
        name = self.p_name(r, c)
        if self.record:
            self.used.add((r, c))
        self.reads.add((r, c))
        if self.reread and not self.record and (r, c) not in self.stored:
            return (1, "%s[%s]" % (self.src, self.index(r, c)))
        if name not in self.loaded:
            self.loaded.add(name)
            self.lines.append("const se23_real_t %s = %s[%s];"
                              % (name, self.src, self.index(r, c)))
        return (1, name)

    def index(self, r, c):
        """The C index of entry (r, c)."""
        if self.stride is not None:
            return "%d" % (self.stride * r + c)
        row = {0: "", 1: "stride"}.get(r, "(stride * %d)" % r)
        if not row:
            return "%d" % c
        return row if c == 0 else "%s + %d" % (row, c)

    def m_block(self, r0, c0):
        """The 3x3 block of a general (not symmetric) input at (r0, c0)."""
        return [[("P", r0 + a, c0 + b) for b in range(3)] for a in range(3)]

    def p_block(self, r0, c0):
        """The 3x3 block of P at (r0, c0), r0 <= c0 (upper triangle)."""
        blk = [[None] * 3 for _ in range(3)]
        for a in range(3):
            for b in range(3):
                r, c = r0 + a, c0 + b
                if r <= c:
                    blk[a][b] = ("P", r, c)
                else:
                    blk[a][b] = ("P", c, r)
        return blk

    def value(self, e):
        """The local of an entry: a lazily loaded P entry is read, a lazy
        sum (from lin) is emitted, the first time either is needed."""
        if e is None:
            return None
        if e[0] == "P":
            return self.load(e[1], e[2])
        if e[0] == "L":
            lazy = self.lazy[e[1]]
            if lazy[0] is None:
                base, products = lazy[1], lazy[2]
                terms = []
                if base is not None:
                    s, nm = self.value(base)
                    terms.append((s, [nm]))
                for a, b in products:
                    sa, na = self.value(a)
                    sb, nb = self.value(b)
                    terms.append((sa * sb, [na, nb]))
                lazy[0] = self.emit(terms)
            return lazy[0]
        return e

    # --- statements ---------------------------------------------------------
    def emit(self, terms):
        """Local = the signed sum of products `terms` [(sign, [names])]; a
        single unsigned factor is returned as it is, without a statement."""
        if not terms:
            return None
        # the unit factor of an added block (lin's extra) is not multiplied
        terms = [(sg, [f for f in fs if f != ONE[1]] or [ONE[1]]) for sg, fs in terms]
        if self.reread:
            terms = [(sg, [self.inputs.get(f, f) for f in fs]) for sg, fs in terms]
        if len(terms) == 1 and len(terms[0][1]) == 1:
            return (terms[0][0], terms[0][1][0])
        # a lone factor (the block being added to) goes first
        terms = sorted(terms, key=lambda t: len(t[1]))
        for _, factors in terms:
            for f in factors:
                if f in self.inputs:
                    self.lines.append("const se23_real_t %s = %s;" % (f, self.inputs.pop(f)))
        out = ""
        for n, (sign, factors) in enumerate(terms):
            prod = " * ".join(factors)
            self.muls += len(factors) - 1
            if n == 0:
                out = ("-" if sign < 0 else "") + prod
            else:
                self.adds += 1
                out += (" - " if sign < 0 else " + ") + prod
        self.ntmp += 1
        name = "t%d" % self.ntmp
        self.lines.append(wrap_statement("const se23_real_t %s = %s;" % (name, out)))
        self.flush()
        return (1, name)

    def lin(self, pairs, base=None, sym=False, extra=None):
        """base (+ the block extra) + sum of L M over pairs (L, M); with sym
        the result is symmetric: the upper triangle is computed and
        mirrored. Entries are emitted when first needed, so unused ones
        cost nothing."""
        out = [[None] * 3 for _ in range(3)]
        for i in range(3):
            for j in range(i if sym else 0, 3):
                b = base[i][j] if base is not None else None
                products = [(L[i][k], M[k][j]) for L, M in pairs for k in range(3)
                            if L[i][k] is not None and M[k][j] is not None]
                if extra is not None and extra[i][j] is not None:
                    if b is None:
                        b = extra[i][j]
                    else:  # base + extra: a product with the unit factor
                        products.append((extra[i][j], ONE))
                if b is None and not products:
                    continue
                self.lazy.append([None, b, products])
                out[i][j] = ("L", len(self.lazy) - 1)
                if sym:
                    out[j][i] = out[i][j]
        return out

    def scale(self, s, B):
        """s B, s the name of a scalar."""
        return self.lin([(diag(s), B)])

    # --- stores -------------------------------------------------------------
    def put_block(self, i, j, blk):
        """Scratch block (i, j) of S (never aliasing P) = blk; a diagonal
        block's upper triangle only."""
        for a in range(3):
            for b in range(a if i == j else 0, 3):
                e = self.value(blk[a][b])
                dst = scratch_entry(i, j, a, b)
                if e is not None and e[0] > 0 and dst in (e[1], self.inputs.get(e[1])):
                    continue  # the entry is unchanged
                rhs = "SE23_R(0)" if e is None else ("-" if e[0] < 0 else "") + e[1]
                self.lines.append("%s = %s;" % (dst, rhs))

    def store_block(self, r0, c0, blk, mirror):
        for a in range(3):
            for b in range(3):
                e = self.value(blk[a][b])
                self.pending.append((r0 + a, c0 + b, e))
                if mirror:
                    self.pending.append((c0 + b, r0 + a, e))
        self.flush()

    def store(self, r, c, e):
        self.pending.append((r, c, self.value(e)))
        self.flush()

    def flush(self):
        """Emits every pending store whose location's value in P is no
        longer needed: read already, or never read."""
        keep = []
        for r, c, e in self.pending:
            name = self.p_name(r, c)
            if (r, c) in self.used and name not in self.loaded:
                keep.append((r, c, e))
                continue
            if e is None:
                rhs = "SE23_R(0)"
            else:
                rhs = ("-" if e[0] < 0 else "") + e[1]
            self.lines.append("%s[%s] = %s;" % (self.dst, self.index(r, c), rhs))
            self.stored.add((r, c))
            self.stores += 1
        self.pending = keep

    def finish(self):
        """The stores still waiting: load their entries first."""
        for r, c, _ in self.pending:
            self.load(r, c)
        self.flush()
        assert not self.pending


ONE = (1, "SE23_R(1)")


def wrap_statement(line, width=96):
    """line broken before a + or - past width (the function body is
    indented by 4), continuations aligned after the =."""
    if len(line) + 4 <= width:
        return line
    indent = " " * (line.index("= ") + 2)
    out, cur = [], ""
    for tok in line.replace(" + ", "\0+ ").replace(" - ", "\0- ").split("\0"):
        if cur and len(cur) + 1 + len(tok) + 4 > width:
            out.append(cur)
            cur = indent + tok
        else:
            cur = tok if not cur else cur + " " + tok
    out.append(cur)
    return "\n    ".join(out)


def diag(s):
    return [[(1, s) if i == j else None for j in range(3)] for i in range(3)]


def skew(v, sign):
    """sign v^ for the vector of locals v0, v1, v2."""
    x, y, z = v + "0", v + "1", v + "2"
    return [[None, (-sign, z), (sign, y)],
            [(sign, z), None, (-sign, x)],
            [(-sign, y), (sign, x), None]]


def tr(B):
    return [[B[j][i] for j in range(3)] for i in range(3)]


def named(prefix):
    return [[(1, "%s%d%d" % (prefix, i, j)) for j in range(3)] for i in range(3)]


PHI, NU, RHO = 0, 1, 2


def kernel(g, mode):
    """The stages of the covariance step (cov_step.h) up to the scratch S
    of the pose blocks before the rotation, on Gen g; each is a function of
    its own, so that none holds another's values in registers. S = E:
    "noise9" for 9 states (E = Bt N Bt^T); for 15, "bias15g" and "bias15a"
    store the cross blocks of the gyro and the accel bias and E by bias
    column (from Y = G C and Zq = Y + Bt Bb + Bt N), then "bias15w" the
    bias block Bb + W, after both stages that read Bb (out may alias P).
    Then "shear", for both: S += G X G^T."""
    R = named("r")
    Rt = tr(R)
    Vp, Vm = skew("vel", 1), skew("vel", -1)
    Pp, Pm = skew("pos", 1), skew("pos", -1)
    dtI = diag("dt")
    Bt = [[input_block(i, k) for k in range(2)] for i in range(3)]
    qs = ["qg", "qa"]

    def X(i, j):
        return g.p_block(3 * i, 3 * j) if i <= j else tr(g.p_block(3 * j, 3 * i))

    def shear(B0, B1, B2):
        """The rows of G [B0; B1; B2]: B0, B1 - v^ B0, B2 + dt B1 - p^ B0."""
        return (B0, g.lin([(Vm, B0)], base=B1), g.lin([(dtI, B1), (Pm, B0)], base=B2))

    # W = G X, by block columns j; W_0j = X_0j.
    W = [[None] * 3 for _ in range(3)]
    for j in range(3):
        W[0][j], W[1][j], W[2][j] = X(0, j), None, None
    if mode in ("bias15g", "bias15a"):
        # one stage per bias column k (gyro, then accel), so that only
        # column k's Y and Zq are live: S = the k = 0 terms of E, then
        # S += the k = 1 terms
        k = 0 if mode == "bias15g" else 1
        Bb = bias_blocks(g)
        Y = shear(g.p_block(0, 9 + 3 * k), g.p_block(3, 9 + 3 * k), g.p_block(6, 9 + 3 * k))
        # by block columns j of S, so that of Zq only column j's is live
        for j in range(3):
            pairs = [(Bt[j][l], Bb[l][k]) for l in range(2) if Bt[j][l] is not None]
            Z = g.lin(pairs, base=Y[j])
            Zq = Z if Bt[j][k] is None else g.lin([(diag(qs[k]), Bt[j][k])], base=Z)
            g.store_block(3 * j, 9 + 3 * k, g.lin([(Rt, Z)]), mirror=True)
            for i in range(j + 1):
                pairs = []
                if Bt[i][k] is not None:
                    pairs.append((Bt[i][k], tr(Zq)))
                if Bt[j][k] is not None:
                    pairs.append((Y[i], tr(Bt[j][k])))
                prev = scratch_block(i, j) if k == 1 else None
                g.put_block(i, j, g.lin(pairs, sym=(i == j), extra=prev))
        g.finish()
        return
    if mode == "bias15w":
        Bb = bias_blocks(g)
        ws = ["wg", "wa"]  # the bias block, Bb + W
        for kb in range(2):
            for lb in range(kb, 2):
                blk = Bb[kb][lb]
                for a in range(3):
                    for b in range(3):
                        r, c = 9 + 3 * kb + a, 9 + 3 * lb + b
                        if r > c:
                            continue
                        e = blk[a][b]
                        if r == c:
                            e = g.value(e)
                            e = g.emit([(e[0], [e[1]]), (1, [ws[kb]])])
                        g.store(r, c, e)
                        if r != c:
                            g.store(c, r, e)
        g.finish()
        return
    if mode == "noise9":
        qBtT = [[tr(g.scale(qs[k], Bt[j][k])) if Bt[j][k] is not None else None
                 for k in range(2)] for j in range(3)]
        for i in range(3):
            for j in range(i, 3):
                pairs = [(Bt[i][k], qBtT[j][k]) for k in range(2)
                         if Bt[i][k] is not None and Bt[j][k] is not None]
                g.put_block(i, j, g.lin(pairs, sym=(i == j)))
        g.finish()
        return

    def finish(i, j, A_pairs, A_base):
        """Scratch block (i, j) += A_ij (upper triangle if i = j)."""
        S = g.lin(A_pairs, base=A_base, sym=(i == j), extra=scratch_block(i, j))
        g.put_block(i, j, S)

    # The in-place order: (2,2), (1,2), (1,1), (0,2), (0,1), (0,0).
    W[1][0], W[2][0] = shear(X(0, 0), X(1, 0), X(2, 0))[1:]
    W[1][1], W[2][1] = shear(X(0, 1), X(1, 1), X(2, 1))[1:]
    W[1][2], W[2][2] = shear(X(0, 2), X(1, 2), X(2, 2))[1:]
    # A_i2 = W_i0 p^ + dt W_i1 + W_i2, A_i1 = W_i0 v^ + W_i1, A_00 = W_00.
    finish(RHO, RHO, [(W[2][0], Pp), (W[2][1], dtI)], W[2][2])
    finish(NU, RHO, [(W[1][0], Pp), (W[1][1], dtI)], W[1][2])
    finish(NU, NU, [(W[1][0], Vp)], W[1][1])
    finish(PHI, RHO, [(W[0][0], Pp), (W[0][1], dtI)], W[0][2])
    finish(PHI, NU, [(W[0][0], Vp)], W[0][1])
    finish(PHI, PHI, [], W[0][0])
    g.finish()


# Offsets of the scratch's blocks in se23_cov_pose_t.e (cov_step.h): the
# blocks i <= j in the order (0,0), (0,1), (0,2), (1,1), (1,2), (2,2), a
# diagonal block as its upper triangle by rows (6), the others by rows (9).
SCRATCH_OFFSET = {(0, 0): 0, (0, 1): 6, (0, 2): 15, (1, 1): 24, (1, 2): 30, (2, 2): 39}
DIAG_UPPER = {(0, 0): 0, (0, 1): 1, (0, 2): 2, (1, 1): 3, (1, 2): 4, (2, 2): 5}


def scratch_entry(i, j, a, b):
    """The C lvalue of entry (a, b) of scratch block (i, j), i <= j (a <= b
    if i = j)."""
    k = DIAG_UPPER[(a, b)] if i == j else 3 * a + b
    return "S->e[%d]" % (SCRATCH_OFFSET[(i, j)] + k)


def bias_blocks(g):
    """The bias x bias blocks Bb[k][l] of P (k, l in {g, a}), from its
    upper triangle."""
    return [[g.p_block(9 + 3 * k, 9 + 3 * l) if k <= l else tr(g.p_block(9 + 3 * l, 9 + 3 * k))
             for l in range(2)] for k in range(2)]


def scratch_block(i, j):
    """Block (i, j) of the scratch S as locals (diagonal blocks: the upper
    triangle, mirrored)."""
    S = named("s%d%d_" % (i, j))
    if i == j:
        for a in range(3):
            for b in range(a):
                S[a][b] = S[b][a]
    return S


def rotate_kernel(g):
    """out's pose blocks (i, j), i <= j, and their mirrors = R^T S_ij R,
    S the scratch of the first stage (diagonal blocks: upper triangles)."""
    R = named("r")
    Rt = tr(R)
    for i in range(3):
        for j in range(i, 3):
            T = g.lin([(Rt, scratch_block(i, j))])
            g.store_block(3 * i, 3 * j, g.lin([(T, R)], sym=(i == j)), mirror=(i != j))
    g.finish()


def left_kernel(g):
    """The left form (cov_step.h): P <- F P F^T + Bl N Bl^T in place, 9x9
    of stride 9, Bt's locals standing for Bl. F = I but for its (rho, nu)
    block dt I, so only the rho row and column shear:
      (rho, rho) += dt (X_nu,rho + X_rho,nu) + dt^2 X_nu,nu,
      (nu, rho) += dt X_nu,nu,  (phi, rho) += dt X_phi,nu."""
    Bt = [[input_block(i, k) for k in range(2)] for i in range(3)]
    qs = ["qg", "qa"]
    qBtT = [[tr(g.scale(qs[k], Bt[j][k])) if Bt[j][k] is not None else None
             for k in range(2)] for j in range(3)]
    dtI = diag("dt")
    g.lines.append("const se23_real_t dt2 = dt * dt;")
    g.muls += 1

    def X(i, j):
        return g.p_block(3 * i, 3 * j) if i <= j else tr(g.p_block(3 * j, 3 * i))

    shear = {(RHO, RHO): [(dtI, X(NU, RHO)), (dtI, X(RHO, NU)), (diag("dt2"), X(NU, NU))],
             (NU, RHO): [(dtI, X(NU, NU))],
             (PHI, RHO): [(dtI, X(PHI, NU))]}
    # The in-place order: a block is stored after the blocks that read it.
    for i, j in ((RHO, RHO), (NU, RHO), (NU, NU), (PHI, RHO), (PHI, NU), (PHI, PHI)):
        pairs = [(Bt[i][k], qBtT[j][k]) for k in range(2)
                 if Bt[i][k] is not None and Bt[j][k] is not None]
        blk = g.lin(pairs + shear.get((i, j), []), base=X(i, j), sym=(i == j))
        g.store_block(3 * i, 3 * j, blk, mirror=(i != j))
    g.finish()


def left_jac_kernel(g):
    """The left form's J <- F J + Bl in place, J 9x6 of stride 6: the rho
    rows gain dt times the nu rows, every block its Bl block."""
    dtI = diag("dt")
    for k in range(2):
        J1, J2 = g.m_block(3, 3 * k), g.m_block(6, 3 * k)
        rows = [g.lin([], base=g.m_block(0, 3 * k), extra=input_block(PHI, k)),
                g.lin([], base=J1, extra=input_block(NU, k)),
                g.lin([(dtI, J1)], base=J2, extra=input_block(RHO, k))]
        for i in range(3):
            if input_block(i, k) is not None or i == RHO:
                g.store_block(3 * i, 3 * k, rows[i], mirror=False)
    g.finish()


def left_input_kernel(g):
    """Bt <- Ad_{Delta+} D Bt in place (cov_step.h): R Bt's blocks, and the
    gyro column's nu and rho blocks gain v^ and p^ times its phi block
    R Bt_phi,g (the phi row has no accel block). Each block's values are
    computed before any of its entries is stored, R Bt_phi,g's last."""
    R = named("r")
    RB0 = g.lin([(R, input_block(PHI, 0))])
    for i, k in ((NU, 0), (NU, 1), (RHO, 0), (RHO, 1)):
        pairs = [(R, input_block(i, k))]
        if k == 0:
            pairs.append((skew("vel" if i == NU else "pos", 1), RB0))
        blk = g.lin(pairs)
        vals = [[g.value(blk[a][b]) for b in range(3)] for a in range(3)]
        for a in range(3):
            for b in range(3):
                g.lines.append("Bt->blk[%d][%d].m[%d][%d] = %s;" % (i, k, a, b, vals[a][b][1]))
    vals = [[g.value(RB0[a][b]) for b in range(3)] for a in range(3)]
    for a in range(3):
        for b in range(3):
            g.lines.append("Bt->blk[0][0].m[%d][%d] = %s;" % (a, b, vals[a][b][1]))


def input_block(i, k):
    """Block (i, k) of Bt as locals; None for its zero block (phi, accel)."""
    return None if (i == PHI and k == 1) else named("b%d%d_" % (i, k))


def inputs(rot="U->R.m", vel="U->v.v", pos="U->p.v"):
    """The reads of U (or of the rotation, velocity and position named),
    Bt, q and S, by the names of their entries: a local declared at first
    use, or with Gen.reread the read itself at every use (they cannot
    alias out, so their reads may follow stores)."""
    ins = {}
    for i in range(3):
        for j in range(3):
            ins["r%d%d" % (i, j)] = "%s[%d][%d]" % (rot, i, j)
        ins["vel%d" % i] = "%s[%d]" % (vel, i)
        ins["pos%d" % i] = "%s[%d]" % (pos, i)
        for k in range(2):
            if i == PHI and k == 1:
                continue
            for a in range(3):
                for b in range(3):
                    ins["b%d%d_%d%d" % (i, k, a, b)] = "Bt->blk[%d][%d].m[%d][%d]" % (i, k, a, b)
    for name in ("qg", "qa", "wg", "wa"):
        ins[name] = "q->" + name
    for i in range(3):
        for j in range(i, 3):
            for a in range(3):
                for b in range(a if i == j else 0, 3):
                    ins["s%d%d_%d%d" % (i, j, a, b)] = scratch_entry(i, j, a, b)
    return ins


# name, what it is, parameters
SIGNATURES = {
    "noise9": ("se23_cov_step9_noise", "9 states, first stage: S = E = Bt N Bt^T",
               "const se23_input_blocks_t *Bt, const se23_step_noise_t *q,\n"
               "se23_cov_pose_t *S"),
    "bias15g": ("se23_cov_step15_gyro", "15 states, first stage: the gyro-bias "
                "cross blocks, S = E's gyro terms",
                "const se23_pose_t *U, se23_real_t dt, const se23_input_blocks_t *Bt,\n"
                "const se23_step_noise_t *q, const se23_real_t *P, se23_real_t *out,\n"
                "se23_cov_pose_t *S"),
    "bias15a": ("se23_cov_step15_accel", "15 states, second stage: the accel-bias "
                "cross blocks, S += E's accel terms",
                "const se23_pose_t *U, se23_real_t dt, const se23_input_blocks_t *Bt,\n"
                "const se23_step_noise_t *q, const se23_real_t *P, se23_real_t *out,\n"
                "se23_cov_pose_t *S"),
    "bias15w": ("se23_cov_step15_bias", "15 states, third stage: the bias block",
                "const se23_step_noise_t *q, const se23_real_t *P, se23_real_t *out"),
    "shear": ("se23_cov_shear_pose", "9 and 15 states, after E: S += G X G^T",
              "const se23_pose_t *U, se23_real_t dt, const se23_real_t *P, int stride,\n"
              "se23_cov_pose_t *S"),
    "rotate": ("se23_cov_rotate_pose", "the last stage: the pose blocks R^T S R",
               "const se23_pose_t *U, const se23_cov_pose_t *S, se23_real_t *out,\n"
               "int stride"),
}


def function(mode):
    def run(g):
        if mode == "rotate":
            rotate_kernel(g)
        else:
            kernel(g, mode)
    reread = mode in ("bias15g", "bias15a")
    # The bias stages exist only for 15 states, whose covariance always has
    # row stride SE23_GAUSS_NMAX: constant offsets (loads with an immediate,
    # no address arithmetic). The pose stages serve strides 9 and 15.
    stride = 15 if mode.startswith("bias15") else None
    g = two_pass(run, reread=reread, stride=stride)
    name, what, params = SIGNATURES[mode]
    pad = " " * (len(name) + 6)
    io = ("; reads %d entries of P, stores %d" % (len(g.reads), g.stores)
          if g.reads or g.stores else "")
    doc = textwrap.wrap("%s: %d multiplies and %d adds (fused into multiply-adds "
                        "where the target has them)%s." % (what, g.muls, g.adds, io), 72,
                        break_on_hyphens=False)
    doc = "/* " + "\n * ".join(doc) + " */\n"
    sig = "void %s(%s)\n" % (name, params.replace("\n", "\n" + pad))
    return doc + sig + "{\n" + "\n".join("    " + x for x in g.lines) + "\n}\n"


def two_pass(kernel, **kw):
    """Runs kernel twice: a probe that records which entries of the source
    are read and stored, then the emitting pass that knows them (loads
    before the stores that replace them)."""
    probe = Gen(**kw)
    probe.inputs = inputs()
    kernel(probe)
    g = Gen(used=probe.used, stored=probe.stored, **kw)
    g.inputs = inputs()
    kernel(g)
    return g


def left_functions():
    """se23_input_blocks_left, se23_cov_left_step, se23_cov_left_jac_step."""
    out = []
    g = Gen()
    g.inputs = inputs(rot="R->m", vel="v->v", pos="p->v")
    left_input_kernel(g)
    out.append(("/* %d multiplies and %d adds. */\n"
                "void se23_input_blocks_left(const se23_mat3_t *R, const se23_vec3_t *v, "
                "const se23_vec3_t *p,\n"
                "                            se23_input_blocks_t *Bt)\n" % (g.muls, g.adds), g))
    g = two_pass(left_kernel, src="Q", dst="Q", stride=9)
    out.append(("/* %d multiplies and %d adds; reads %d entries of Q, stores %d. */\n"
                "void se23_cov_left_step(se23_real_t dt, const se23_input_blocks_t *Bt,\n"
                "                        const se23_step_noise_t *q, se23_real_t *Q)\n"
                % (g.muls, g.adds, len(g.reads), g.stores), g))
    g = two_pass(left_jac_kernel, src="J->m", dst="J->m", stride=6, prefix="j")
    out.append(("/* %d multiplies and %d adds, %d reads of J, %d stores. */\n"
                "void se23_cov_left_jac_step(se23_real_t dt, const se23_input_blocks_t *Bt,\n"
                "                            se23_mat9x6_t *J)\n"
                % (g.muls, g.adds, len(g.reads), g.stores), g))
    return ["%s{\n%s\n}\n" % (head, "\n".join("    " + x for x in g.lines)) for head, g in out]


def source():
    parts = []
    for mode in ("noise9", "bias15g", "bias15a", "bias15w", "shear", "rotate"):
        parts.append(function(mode))
    parts.extend(left_functions())
    return ("/* Generated by tools/gen/gen_cov_step.py: do not edit; change the\n"
            " * generator and run it (make check fails while this file is stale).\n"
            " *\n"
            " * The per-sample kernels of cov_step.h as straight-line code: the\n"
            " * covariance step out = Phi P Phi^T + diag(B_k N B_k^T, W) (the block\n"
            " * algorithm of cov_step.c's file comment) and the steps of a\n"
            " * preintegrated factor's left form (cov_step.h), every 3x3 product\n"
            " * expanded and its structural zeros skipped. */\n"
            "#include \"../cov_step.h\"\n\n" + "\n".join(parts))


def main():
    text = source()
    if "--check" in sys.argv[1:]:
        try:
            with open(OUT) as f:
                current = f.read()
        except OSError:
            current = ""
        if current != text:
            print("src/cov/gen/cov_step_kernel.c is stale: run python3 tools/gen/gen_cov_step.py",
                  file=sys.stderr)
            return 1
        return 0
    with open(OUT, "w") as f:
        f.write(text)
    return 0


if __name__ == "__main__":
    sys.exit(main())
