"""Compiled sweep of the Gauss-Seidel solution of the radiosity equations."""

from ._jit import kernel


@kernel
def gauss_seidel_sweep(f, rho, e, b):
    """One Gauss-Seidel sweep over ``b`` (P, 3) in place: for each patch i in turn,
    B_i = (E_i + rho_i sum_{j != i} F_ij B_j) / (1 - rho_i F_ii), with the B_j already
    updated in this sweep.  Returns the largest change of any B_i."""
    p = f.shape[0]
    change = 0.0
    for i in range(p):
        s0 = 0.0
        s1 = 0.0
        s2 = 0.0
        for j in range(p):
            if j != i:
                s0 += f[i, j] * b[j, 0]
                s1 += f[i, j] * b[j, 1]
                s2 += f[i, j] * b[j, 2]
        for c in range(3):
            s = s0 if c == 0 else (s1 if c == 1 else s2)
            new = (e[i, c] + rho[i, c] * s) / (1.0 - rho[i, c] * f[i, i])
            d = abs(new - b[i, c])
            if d > change:
                change = d
            b[i, c] = new
    return change
