# Generates tests/data/wsgb_independent.json (run from crates/cagd-cli: python3 tests/data/wsgb_reference.py).
# Independent reference (spec formulas only) to make unseen wsgb_reduce_003 vectors.
from fractions import Fraction as F
from math import comb
import json, random

def terms(n, L):
    h = n // 2; t = []
    for i in range(n + 1):
        if i < L: t.append((2**i, i, i + 2))
        elif i < (n + 1) // 2: t.append((2**L * comb(h + i - 2*L, i - L), i, h + 1))
        elif n % 2 == 0 and i == h: t.append((2**L * comb(n - 2*L, h - L), h, h))
        else:
            K, a, b = t[n - i]; t.append((K, b, a))
    return t

def D(n, L):  # Bernstein coefficient matrix, column i = beta_i
    M = [[F(0)] * (n + 1) for _ in range(n + 1)]
    for i, (K, a, b) in enumerate(terms(n, L)):
        for k in range(a, n - b + 1):
            M[k][i] = F(K * comb(n - a - b, k - a), comb(n, k))
    return M

def solve(M, rhs):
    n = len(M); A = [row[:] + [rhs[i]] for i, row in enumerate(M)]
    for c in range(n):
        p = next(r for r in range(c, n) if A[r][c] != 0); A[c], A[p] = A[p], A[c]
        for r in range(n):
            if r != c and A[r][c] != 0:
                f = A[r][c] / A[c][c]; A[r] = [x - f * y for x, y in zip(A[r], A[c])]
    return [A[i][n] / A[i][i] for i in range(n)]

def lec(P, L):
    n = len(P) - 1; m = n // 2; dim = len(P[0])
    if n % 2: K = 2**L * comb(2*m - 2*L, m - L); s = (-1)**m; Dv = [P[m+1][d] - P[m][d] for d in range(dim)]
    else: K = 2**L * comb(2*m - 2*L - 1, m - L - 1); s = (-1)**(m+1); Dv = [P[m-1][d] - 2*P[m][d] + P[m+1][d] for d in range(dim)]
    return [s * K * x for x in Dv], Dv

def inv_elev(P, L):
    n = len(P) - 1; m = n // 2; dim = len(P[0])
    if n % 2: return [P[i] if i <= m else P[i+1] for i in range(n)]
    q = [None] * n
    for i in range(m):
        if i < L: q[i] = P[i]; q[n-1-i] = P[n-i]
        else:
            q[i] = [((m+i-2*L) * P[i][d] - (i-L) * (P[i-1][d] if i > L else 0)) / (m - L) for d in range(dim)]
            q[n-1-i] = [((m+i-2*L) * P[n-i][d] - (i-L) * (P[n-i+1][d] if i > L else 0)) / (m - L) for d in range(dim)]
    return q

def perturb(P, L):
    n = len(P) - 1; m = n // 2; P = [row[:] for row in P]; dim = len(P[0])
    _, Dv = lec(P, L)
    for d in range(dim):
        if n % 2: mid = (P[m][d] + P[m+1][d]) / 2; P[m][d] = mid; P[m+1][d] = mid
        else:
            P[m-1][d] -= Dv[d] / 6; P[m][d] += Dv[d] / 3; P[m+1][d] -= Dv[d] / 6
    return inv_elev(P, L)

def uniform(P, L):
    n = len(P) - 1; dim = len(P[0])
    alpha = [F((-1)**(n-i) * comb(2*n, 2*i), comb(n, i)) for i in range(n + 1)]
    g = solve(D(n, L), alpha)
    lc, _ = lec(P, L)
    hat = [[P[i][d] - g[i] * lc[d] / 2**(2*n-1) for d in range(dim)] for i in range(n + 1)]
    return inv_elev(hat, L)

def ev(P, L, u):
    n = len(P) - 1
    return [sum(K * u**a * (1-u)**b * P[i][d] for i, (K, a, b) in enumerate(terms(n, L))) for d in range(len(P[0]))]

def fs(x): return str(x.numerator) if x.denominator == 1 else f"{x.numerator}/{x.denominator}"

random.seed(3)
out = []
for (n, L, dim, meth) in [(9,3,3,"perturb"),(9,3,3,"uniform"),(8,2,3,"uniform"),(8,1,2,"perturb"),(8,1,2,"uniform"),(2,0,2,"perturb"),(3,0,1,"uniform"),(10,0,3,"perturb"),(12,3,2,"perturb"),(11,2,2,"uniform"),(4,1,3,"perturb"),(5,1,2,"perturb")]:
    P = [[F(random.randint(-500, 500)) for _ in range(dim)] for _ in range(n + 1)]
    Q = perturb(P, L) if meth == "perturb" else uniform(P, L)
    Lp = min(L, max((n-1)//2 - 1, 0))
    lc, Dv = lec(P, L); m = n // 2
    pb = 2**L * comb(2*m - 2*L, m - L) * max(abs(x) for x in Dv) / 4**m
    ue = max(abs(x) for x in lc) / 2**(2*n-1)
    Pf = [[float(x) for x in r] for r in P]; Qf = [[float(x) for x in r] for r in Q]
    tm = max(max(abs(a - b) for a, b in zip(ev(Pf, L, j/4000), ev(Qf, Lp, j/4000))) for j in range(4001))
    out.append({"id": f"py-{n}-{L}-{dim}-{meth}", "algorithm": "wsgb_reduce_003",
        "params": {"n": n, "L": L, "method": meth, "norm": "inf (max abs coordinate)"},
        "input": {"P": [[int(x) for x in r] for r in P]},
        "expected": {"Q": Qf, "Q_exact": [[fs(x) for x in r] for r in Q], "lec": [float(x) for x in lc],
                     "paper_bound_11": float(pb), "uniform_error_12": float(ue), "true_max_error_inf": tm},
        "tol": 1e-9})
for (n, L) in [(9, 3), (12, 5), (6, 0), (1, 0), (0, 0)]:
    out.append({"id": f"py-basis-{n}-{L}", "algorithm": "wsgb_basis", "params": {"n": n, "L": L}, "input": {},
                "expected": {"terms_K_a_b": [[str(K), a, b] for K, a, b in terms(n, L)]}, "tol": 0})
json.dump(out, open("tests/data/wsgb_independent.json", "w"), indent=1)
print(len(out))
