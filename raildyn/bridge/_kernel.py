"""The time march of a vehicle crossing a bridge, compiled with numba.

Every step the axles stand somewhere else on the beam, so the coupled mass, damping
and stiffness matrices change and the step's equations are assembled and solved
afresh: a few hundred small operations where numpy's per-call cost would dominate.
:func:`raildyn.bridge.coupled.crossing` checks every input and documents the
equations; nothing here checks anything.

The mode shapes come as tables on a uniform grid over the beam (φ, φ′ and φ″ at
each point): φ and φ′ are interpolated by cubic Hermite polynomials (from φ′ and φ″),
φ″ linearly.
"""

from __future__ import annotations

import numba
import numpy as np

__all__ = ["march"]


@numba.njit(cache=True)
def _shapes(x, length, dx, phi, dphi, ddphi, out):
    """φ, φ′, φ″ of every mode at x into out[0:3, :]; zero off the beam."""
    n = phi.shape[0]
    if x < 0.0 or x > length:
        for i in range(n):
            out[0, i] = 0.0
            out[1, i] = 0.0
            out[2, i] = 0.0
        return False
    g = min(int(x / dx), phi.shape[1] - 2)
    s = x / dx - g
    h00 = (1.0 + 2.0 * s) * (1.0 - s) ** 2
    h10 = s * (1.0 - s) ** 2
    h01 = s * s * (3.0 - 2.0 * s)
    h11 = s * s * (s - 1.0)
    for i in range(n):
        out[0, i] = h00 * phi[i, g] + h10 * dx * dphi[i, g] + h01 * phi[i, g + 1] + h11 * dx * dphi[i, g + 1]
        out[1, i] = (
            h00 * dphi[i, g] + h10 * dx * ddphi[i, g] + h01 * dphi[i, g + 1] + h11 * dx * ddphi[i, g + 1]
        )
        out[2, i] = (1.0 - s) * ddphi[i, g] + s * ddphi[i, g + 1]
    return True


@numba.njit(cache=True)
def _assemble(
    t, v, length, dx, phi, dphi, ddphi, Mb, Cb, Kb, M, C, K, GK, GC, KW, CW, W, m, d, r, A, B, Z, f, S
):
    """The coupled M (A), C (B), K (Z) and load f at time t; S (a, 3, n) receives the shapes at the axles."""
    n, p, a = Mb.size, M.shape[0], W.size
    A[:] = 0.0
    B[:] = 0.0
    Z[:] = 0.0
    f[:] = 0.0
    for i in range(n):
        A[i, i] = Mb[i]
        B[i, i] = Cb[i]
        Z[i, i] = Kb[i]
    for i in range(M.shape[0]):  # element by element: ARCHITECTURE.md, compiled kernels
        for j in range(M.shape[1]):
            A[n + i, n + j] = M[i, j]
            B[n + i, n + j] = C[i, j]
            Z[n + i, n + j] = K[i, j]
    on = np.empty(a, dtype=np.int64)  # the axles on the beam: only they load it
    count = 0
    for j in range(a):
        if _shapes(v * t - d[j], length, dx, phi, dphi, ddphi, S[j]):
            on[count] = j
            count += 1
    # the vehicle's rail inputs u = −Φᵀb + r, u̇ = −Φᵀḃ − vΦ′ᵀb + v r′ and ü (module docstring)
    for j in range(a):
        for k in range(p):
            f[n + k] += GK[k, j] * r[j, 0] + GC[k, j] * v * r[j, 1]
    for jj in range(count):
        j = on[jj]
        load = W[j] + m[j] * v * v * r[j, 2]
        for k in range(a):
            load += KW[j, k] * r[k, 0] + CW[j, k] * v * r[k, 1]
        for i in range(n):
            pi = S[j, 0, i]
            f[i] += pi * load
            for ii in range(n):
                A[i, ii] += m[j] * pi * S[j, 0, ii]
                B[i, ii] += 2.0 * v * m[j] * pi * S[j, 1, ii]
                Z[i, ii] += v * v * m[j] * pi * S[j, 2, ii]
                for kk in range(count):
                    k = on[kk]
                    B[i, ii] += pi * CW[j, k] * S[k, 0, ii]
                    Z[i, ii] += pi * (KW[j, k] * S[k, 0, ii] + v * CW[j, k] * S[k, 1, ii])
            for k in range(p):
                B[i, n + k] += pi * GC[k, j]
                Z[i, n + k] += pi * GK[k, j]
                B[n + k, i] += GC[k, j] * pi
                Z[n + k, i] += GK[k, j] * pi + v * GC[k, j] * S[j, 1, i]


@numba.njit(cache=True)
def _contact(v, n, p, x, xd, xdd, W, m, GK, GC, KW, CW, r, S, F):
    """Each axle's force on the rail, downwards: W + m ü − (G_Kᵀq + G_Cᵀq̇ − K_W u − C_W u̇)."""
    a = W.size
    u = np.empty(a)
    ud = np.empty(a)
    udd = np.empty(a)
    for j in range(a):
        u[j], ud[j], udd[j] = r[j, 0], v * r[j, 1], v * v * r[j, 2]
        for i in range(n):
            u[j] -= S[j, 0, i] * x[i]
            ud[j] -= S[j, 0, i] * xd[i] + v * S[j, 1, i] * x[i]
            udd[j] -= S[j, 0, i] * xdd[i] + 2.0 * v * S[j, 1, i] * xd[i] + v * v * S[j, 2, i] * x[i]
    for j in range(a):
        up = 0.0
        for k in range(p):
            up += GK[k, j] * x[n + k] + GC[k, j] * xd[n + k]
        for k in range(a):
            up -= KW[j, k] * u[k] + CW[j, k] * ud[k]
        F[j] = W[j] + m[j] * udd[j] - up


@numba.njit(cache=True)
def march(
    h, steps, v, length, dx, phi, dphi, ddphi, Mb, Cb, Kb, M, C, K, GK, GC, KW, CW, W, m, d, r, X, V, Acc, F
):
    """Average-acceleration Newmark steps from rest; X, V, Acc (steps + 1, n + p) and F (steps + 1, a) filled.

    r is (steps + 1, a, 3): the rail's height, slope and curvature under each axle at each time.
    Returns the index of the first step whose state is not finite, or −1.
    """
    n, p, a = Mb.size, M.shape[0], W.size
    N = n + p
    A = np.empty((N, N))
    B = np.empty((N, N))
    Z = np.empty((N, N))
    f = np.empty(N)
    S = np.empty((a, 3, n))
    X[0, :] = 0.0
    V[0, :] = 0.0
    for s in range(steps + 1):
        # fmt: off
        _assemble(s * h, v, length, dx, phi, dphi, ddphi, Mb, Cb, Kb, M, C, K, GK, GC, KW, CW, W, m, d,
                  r[s], A, B, Z, f, S)
        # fmt: on
        if s == 0:  # from rest: the acceleration that balances the loads at t = 0
            if not np.all(np.isfinite(f)):
                return 0
            acc = np.linalg.inv(A) @ f  # not np.linalg.solve: ARCHITECTURE.md, compiled kernels
            for i in range(N):
                Acc[0, i] = acc[i]
        else:
            xp = X[s - 1] + h * V[s - 1] + 0.25 * h * h * Acc[s - 1]
            vp = V[s - 1] + 0.5 * h * Acc[s - 1]
            rhs = f - B @ vp - Z @ xp
            if not np.all(np.isfinite(rhs)):
                return s
            acc = np.linalg.inv(A + 0.5 * h * B + 0.25 * h * h * Z) @ rhs
            for i in range(N):
                X[s, i] = xp[i] + 0.25 * h * h * acc[i]
                V[s, i] = vp[i] + 0.5 * h * acc[i]
                Acc[s, i] = acc[i]
            if not np.all(np.isfinite(X[s])):
                return s
        _contact(v, n, p, X[s], V[s], Acc[s], W, m, GK, GC, KW, CW, r[s], S, F[s])
    return -1


@numba.njit(cache=True)
def superpose(omega, zeta, span, speeds, duration, samples, delays, loads, shape, out, accel):
    """Closed-form modal responses of a simply supported beam to constant forces, summed into out (s, k),
    and their second time derivative into accel (s, k).

    Mode j of unit modal load sin(Ω_j t) while a force is on the span (0 ≤ t − τ ≤ T = L/v) is
    q = a sin Ω(t−τ) + b cos Ω(t−τ) + Re{C_f e^{λ(t−τ)}}, λ = −ξω + iω_d, from rest; after it
    leaves, Re{C_e e^{λ(t−τ−T)}} from its state at exit. The forces that have left are carried
    as one complex sum, advanced by e^{λΔt} from sample to sample, and those on the span as two
    (of e^{iΩ(t−τ)} and e^{λ(t−τ)}), so a long train costs O(samples + axles) per mode and speed,
    not their product. ``shape`` holds 2φ_j(x)/(mL).
    The acceleration is the same sums differentiated twice: −Ω² on the harmonic part, λ² on the
    exponentials.
    """
    n = omega.size
    a_count = delays.size
    for si in range(speeds.size):
        v = speeds[si]
        T = span / v
        dt = duration[si] / (samples - 1)
        for j in range(n):
            w = omega[j]
            wd = w * np.sqrt(1.0 - zeta * zeta)
            Om = (j + 1) * np.pi * v / span
            den = (w * w - Om * Om) ** 2 + (2.0 * zeta * w * Om) ** 2
            # undamped at resonance (Ω = ω): q = (sin ωs − ωs cos ωs)/(2ω²), growing while on the span
            resonant = den <= 1e-24 * w**4
            if resonant:
                den = 1.0
            a = (w * w - Om * Om) / den
            b = -2.0 * zeta * w * Om / den
            c = -b
            d = (zeta * w * c - a * Om) / wd
            lam = complex(-zeta * w, wd)
            cf = complex(c, -d)  # Re{(c − id) e^{iω_d t}} = c cos + d sin
            # the state at exit of one unit force, then the free vibration's phasor
            decay = np.exp(-zeta * w * T)
            q_end = (
                a * np.sin(Om * T) + b * np.cos(Om * T) + decay * (c * np.cos(wd * T) + d * np.sin(wd * T))
            )
            qd_end = (
                a * Om * np.cos(Om * T)
                - b * Om * np.sin(Om * T)
                + decay
                * ((d * wd - zeta * w * c) * np.cos(wd * T) - (c * wd + zeta * w * d) * np.sin(wd * T))
            )
            if resonant:
                q_end = (np.sin(w * T) - w * T * np.cos(w * T)) / (2.0 * w * w)
                qd_end = T * np.sin(w * T) / 2.0
            ce = complex(q_end, -(qd_end + zeta * w * q_end) / wd)
            step = np.exp(lam * dt)
            turn = np.exp(1j * Om * dt)
            gone = 0j  # Σ over the forces that have left of P C_e e^{λ(t − τ − T)}
            # Σ over the forces on the span of P e^{iΩ(t − τ)} and of P e^{λ(t − τ)}, advanced like
            # ``gone``: a force's term is added as it enters and taken off as it leaves, so the
            # harmonic and transient parts cost O(1) a sample, not O(forces on the span).
            harmonics = 0j
            transients = 0j
            first_on = 0  # forces [first_on, entered) are on the span
            entered = 0
            for i in range(samples):
                t = i * dt
                if i:
                    gone *= step
                    harmonics *= turn
                    transients *= step
                while first_on < a_count and delays[first_on] / v + T <= t:
                    s = t - delays[first_on] / v
                    if first_on < entered:  # counted on the span: its terms come off
                        harmonics -= loads[first_on] * np.exp(1j * Om * s)
                        transients -= loads[first_on] * np.exp(lam * s)
                    gone += loads[first_on] * ce * np.exp(lam * (s - T))
                    first_on += 1
                while entered < a_count and delays[entered] / v <= t:
                    if entered >= first_on:  # not already gone within this one step
                        s = t - delays[entered] / v
                        harmonics += loads[entered] * np.exp(1j * Om * s)
                        transients += loads[entered] * np.exp(lam * s)
                    entered += 1
                total = gone.real
                second = (lam * lam * gone).real
                if resonant:
                    for k in range(first_on, entered):
                        s = t - delays[k] / v
                        q = (np.sin(w * s) - w * s * np.cos(w * s)) / (2.0 * w * w)
                        total += loads[k] * q
                        second += loads[k] * (np.sin(w * s) - w * w * q)  # q̈ = sin ωs − ω²q
                else:
                    if first_on >= entered:  # nothing on the span: the sums hold round-off only
                        harmonics = 0j
                        transients = 0j
                    harmonic = a * harmonics.imag + b * harmonics.real  # Σ P (a sin Ωs + b cos Ωs)
                    transient = cf * transients
                    total += harmonic + transient.real
                    second += -Om * Om * harmonic + (lam * lam * transient).real
                out[si, i] += shape[j] * total
                accel[si, i] += shape[j] * second
