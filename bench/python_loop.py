#!/usr/bin/env python3
"""Baseline: the flexarm closed loop written the way a control researcher would in Python.

This is the "straightforward alternative" we time the Rust crate `flexarm` against on the
same machine. It simulates the flexible-joint two-link arm with Dahl friction, a Dahl
friction observer (torque compensation), the optional preliminary state feedback K_pr and
the sampled predictive controller (k = 12 backward-Euler steps of size delta/8, each solved
by a Newton loop with a finite-difference Jacobian and numpy.linalg.solve). The plant is
integrated with scipy.integrate.solve_ivp once per sampling interval, the predictive
controller's output is applied one sampling period late (computation delay).

Prints one JSON line to stdout, e.g.
  python bench/python_loop.py --delta 0.01 --duration 10 --pf paper --repeats 3
"""
import argparse
import json
import statistics
import sys
import time

import numpy as np
import scipy
from scipy.integrate import solve_ivp

# ---- plant parameters (SI) -------------------------------------------------------------
A1, A2, A3 = 4.984, 0.247, 0.328
IR1, BV1, BV2 = 1.939, 1.40, 0.20
FC1, FC2 = 4.82, 1.15
EPS1 = EPS2 = 1e-4
K1 = 1152.6
ALPHA = 2.0  # alpha1 = alpha2

# preliminary feedback u = K_PR @ X + v, X = (q1, q2, theta, q1d, q2d, thd, w1, w2); rows T1, T2
K_PR = np.array([[102.3, -0.07, -103.0, 15.97, -0.10, -17.0, 0.0, 0.0],
                 [16.17, -0.01, -16.3, 2.55, -0.02, -2.71, 0.0, 0.0]])

# reference: quintic..9th order rest-to-rest polynomial, same for both links
TF = 1.0
QD0 = np.array([0.0, 1.5 * np.pi])
QDF = np.array([0.5 * np.pi, 0.0])

# ODE method: the Dahl states have time constants eps/|v| ~ 1e-5 s, so the system is stiff.
# LSODA (switches automatically between Adams and BDF) is the usual scipy choice for this.
ODE_METHOD, RTOL, ATOL = "LSODA", 1e-8, 1e-10


def reference(t):
    """qd, qd', qd'' (arrays of 2) at time t."""
    tau = t / TF
    if tau <= 0.0:
        s, ds, dds = 0.0, 0.0, 0.0
    elif tau >= 1.0:
        s, ds, dds = 1.0, 0.0, 0.0
    else:
        s = 126*tau**5 - 420*tau**6 + 540*tau**7 - 315*tau**8 + 70*tau**9
        ds = 630*tau**4 - 2520*tau**5 + 3780*tau**6 - 2520*tau**7 + 630*tau**8
        dds = 2520*tau**3 - 12600*tau**4 + 22680*tau**5 - 17640*tau**6 + 5040*tau**7
    d = QDF - QD0
    return QD0 + d * s, d * ds / TF, d * dds / TF**2


def mass_matrix(q2):
    c2 = np.cos(q2)
    return np.array([[A1 + 2*A3*c2, A2 + A3*c2, 0.0],
                     [A2 + A3*c2, A2, 0.0],
                     [0.0, 0.0, IR1]])


def r_free(q, qdot):
    """Right-hand side r without friction and without input torques."""
    q1, q2, th = q
    q1d, q2d, thd = qdot
    s2 = np.sin(q2)
    return np.array([A3*q2d*(2*q1d + q2d)*s2 + K1*(th - q1),
                     -BV2*q2d - A3*q1d**2*s2,
                     -BV1*thd + K1*(q1 - th)])


def closed_loop_rhs(t, x, v, use_pf):
    """x = (q1,q2,th, q1d,q2d,thd, w1,w2, xf1,xf2, xh1,xh2); v held constant."""
    q, qdot, w = x[0:3], x[3:6], x[6:8]
    xf, xh = x[8:10], x[10:12]
    u = K_PR @ x[0:8] + v if use_pf else v
    T = u + xh  # friction compensation with the observer estimate
    thd, q2d = qdot[2], qdot[1]
    r = r_free(q, qdot) + np.array([0.0, T[1] - xf[1], T[0] - xf[0]])
    qdd = np.linalg.solve(mass_matrix(q[1]), r)
    qd, _, _ = reference(t)
    dw = ALPHA**3 * (q[0:2] - qd)
    dxf = np.array([(-abs(thd)*xf[0] + FC1*thd) / EPS1, (-abs(q2d)*xf[1] + FC2*q2d) / EPS2])
    dxh = np.array([(-abs(thd)*xh[0] + FC1*thd) / EPS1, (-abs(q2d)*xh[1] + FC2*q2d) / EPS2])
    return np.concatenate([qdot, qdd, dw, dxf, dxh])


def step_residual(z, q, qdot, w, eps, tp):
    """Backward-Euler step residual; z = (q1d+, q2d+, thd+, T1+, T2+)."""
    vp, U = z[0:3], z[3:5]
    qp = q + eps * vp
    ap = (vp - qdot) / eps
    qd, dqd, ddqd = reference(tp)
    wp = w + eps * ALPHA**3 * (qp[0:2] - qd)
    dyn = mass_matrix(qp[1]) @ ap - r_free(qp, vp) - np.array([0.0, U[1], U[0]])
    con = (ap[0:2] - ddqd) + 3*ALPHA*(vp[0:2] - dqd) + 3*ALPHA**2*(qp[0:2] - qd) + wp
    return np.concatenate([dyn, con])


def newton(fun, z0, tol=1e-10, max_iter=50):
    """Plain Newton with a forward-difference Jacobian; stops on a small residual or step."""
    z = z0.copy()
    for _ in range(max_iter):
        f = fun(z)
        if np.linalg.norm(f) <= tol * (1.0 + np.linalg.norm(z)):
            return z
        J = np.empty((len(z), len(z)))
        for j in range(len(z)):
            h = 1e-7 * (1.0 + abs(z[j]))
            zh = z.copy()
            zh[j] += h
            J[:, j] = (fun(zh) - f) / h
        dz = np.linalg.solve(J, -f)
        z = z + dz
        if np.linalg.norm(dz) <= tol * (1.0 + np.linalg.norm(z)):
            return z
    raise RuntimeError("Newton did not converge")


def predict(X0, t0, delta, use_pf, k=12):
    """Predictive controller: k backward-Euler steps of size delta/8 from the measured X0."""
    eps = delta / 8.0
    q, qdot, w = X0[0:3].copy(), X0[3:6].copy(), X0[6:8].copy()
    z = np.concatenate([qdot, np.zeros(2)])
    for j in range(k):
        tp = t0 + (j + 1) * eps
        z = newton(lambda zz: step_residual(zz, q, qdot, w, eps, tp), z)
        vp = z[0:3]
        q = q + eps * vp
        qdot = vp
        w = w + eps * ALPHA**3 * (q[0:2] - reference(tp)[0])
    U = z[3:5]
    if use_pf:
        return U - K_PR @ np.concatenate([q, qdot, w])
    return U


def simulate(delta, duration, use_pf):
    """Run the sampled closed loop; returns (sim_seconds, err_slew, err_after, diverged_at)."""
    x = np.zeros(12)
    x[1] = 1.5 * np.pi  # starts at rest on the reference
    v_apply = np.zeros(2)  # on [0, delta) v = 0
    err_slew, err_after = np.zeros(2), np.zeros(2)
    n = int(round(duration / delta))
    t_end = 0.0

    def record(ts, qs):
        """Update max |e| from sample times ts and link angles qs (2 x len(ts)); False if diverged."""
        for t, q12 in zip(ts, qs.T):
            e = np.abs(q12 - reference(t)[0])
            if not np.all(np.isfinite(e)) or np.any(e > np.pi):
                return False
            if t <= TF:
                np.maximum(err_slew, e, out=err_slew)
            else:
                np.maximum(err_after, e, out=err_after)
        return True

    for rho in range(n):
        t0 = rho * delta
        if not np.all(np.isfinite(x)) or not record([t0], x[0:2, None]):
            return t_end, err_slew, err_after, t0
        try:
            v_next = predict(x[0:8], t0, delta, use_pf)
        except (RuntimeError, np.linalg.LinAlgError):
            return t_end, err_slew, err_after, t0
        sol = solve_ivp(closed_loop_rhs, (t0, t0 + delta), x, method=ODE_METHOD,
                        rtol=RTOL, atol=ATOL, args=(v_apply, use_pf))
        if sol.status != 0 or not record(sol.t, sol.y[0:2]):
            return t_end, err_slew, err_after, t0
        x = sol.y[:, -1]
        t_end = t0 + delta
        v_apply = v_next  # computed at t_rho, applied on [t_{rho+1}, t_{rho+2})
    if not record([t_end], x[0:2, None]):
        return t_end, err_slew, err_after, t_end
    return t_end, err_slew, err_after, None


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--delta", type=float, default=0.01, help="sampling period [s]")
    ap.add_argument("--duration", type=float, default=10.0, help="simulated time [s]")
    ap.add_argument("--pf", choices=["off", "paper"], default="paper", help="preliminary feedback")
    ap.add_argument("--repeats", type=int, default=1, help="runs; median wall time is reported")
    args = ap.parse_args()
    use_pf = args.pf == "paper"

    walls = []
    for _ in range(max(1, args.repeats)):
        start = time.perf_counter()
        sim_t, e_slew, e_after, diverged_at = simulate(args.delta, args.duration, use_pf)
        walls.append(time.perf_counter() - start)
    wall = statistics.median(walls)
    print(json.dumps({
        "impl": "python-scipy", "delta": args.delta, "duration": args.duration,
        "preliminary_feedback": args.pf, "wall_seconds": wall, "sim_seconds": sim_t,
        "realtime_factor": sim_t / wall, "max_error_slew": e_slew.tolist(),
        "max_error_after": e_after.tolist(), "diverged_at": diverged_at,
        "repeats": len(walls), "ode_method": ODE_METHOD, "rtol": RTOL, "atol": ATOL,
        "numpy": np.__version__, "scipy": scipy.__version__,
        "python": sys.version.split()[0],
    }))


if __name__ == "__main__":
    main()
