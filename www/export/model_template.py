#!/usr/bin/env python3
"""The sampled loop of von Wissel, Nikoukhah & Campbell (1994), "On a new predictive control
strategy: application to a flexible-joint robot", linearized at rest - exported by flexarm.

State: {{STATE}}

Needs NumPy and SciPy. It rebuilds, for the settings above, the arm linearized at rest, the
predictive controller as a linear map (k backward-Euler steps of eps over the stabilized DAE,
eqs. (2.3)-(2.4), (4.2)-(4.3)), the one-period map of the sampled loop (the torque computed
from x(t_n) is held from t_n + delta to t_n + 2 delta, Fig. 2.1), its eigenvalues and spectral
radius rho (stable iff rho < 1), and the pair A4 the controller leaves as delta -> 0 (section 3).
With sensors on (SENSORS: an encoder, noise, or velocities from differences) the controller is
a digital one that reads only the measured angles: rho is then its 16-state loop's, and the
script predicts the noise floor the angles' error leaves (the discrete Lyapunov equation).
With --simulate it also runs the nonlinear arm under the predictive controller (the friction
taken as cancelled by the observer of eq. (4.4)) and plots the errors if matplotlib is installed:
in a window where there is a display, else saved to flexarm_errors.png (and said where);
--plot FILE.png saves the plot to FILE (any format matplotlib writes, by its extension) and
implies --simulate.

The last line it prints is one JSON object: spectral_radius, limit_pair, eigenvalues, ...
"""
import argparse
import json
import math
import os

import numpy as np
from scipy.linalg import expm, solve_discrete_lyapunov

# ---------------------------------------------------------------------------------- settings
# The arm, eq. (4.1), in the paper's units: inertias kg m^2, damping N m s/rad, friction N m,
# Dahl's eps rad, the joint's stiffness N m/rad.
ARM = {{ARM}}
# The arm the controller assumes (its predictor): the same arm unless model = paper.
MODEL = {{MODEL}}
ALPHA = {{ALPHA}}  # alpha_1, alpha_2 in 1/s: each link error obeys (d/dt + alpha)^3 e = 0, eq. (4.3)
DELTA = {{DELTA}}  # the sampling period delta, s
K = {{K}}  # the predictor's horizon: k backward-Euler steps ...
M = {{M}}  # ... of eps = delta / m (the paper: k = 12, m = 8, so k eps = 1.5 delta)
EPS = DELTA / M
# The preliminary feedback u = K_pr x + v (section 3; zero without it), on
# x = (q1, q2, theta, q1', q2', theta', w1, w2); rows drive T1 (the motor) and T2 (joint 2).
K_PR = np.array({{GAIN}})
INNER = "{{INNER}}"  # "continuous": K_pr x acts at all times; "sampled": held over each period
REST = {{REST}}  # the rest point (q1, q2) the loop is linearized at, rad
SLEW = {{SLEW}}  # the reference: from, to (rad, per link) in slew_time s
# The sensors: encoder counts per revolution N on q1, q2, theta (0 = exact angles), the noise's
# standard deviation sigma on each measured angle (rad), where the velocities come from ("exact",
# as the paper, or "difference" of the measured angles over delta), the time constant tau_v of a
# first-order low-pass filter on that velocity estimate (s, 0 = none), and the torque limit |T1|,
# |T2| <= torque_limit N m (0 = none). All off is the paper's perfect robot; with any of the first
# four on the loop is the digital controller of digital_loop below. The torque limit does not
# enter the linear model: a torque held at its limit is no longer a linear loop.
SENSORS = {{SENSORS}}


# ------------------------------------------------------------------------ the arm, eq. (4.1)
def mass_matrix(p, q2):
    """M(q2) of q = (q1, q2, theta) (ERRATA: A2 + A3 cos q2 off the diagonal)."""
    c2 = math.cos(q2)
    return np.array([[p["a1"] + 2 * p["a3"] * c2, p["a2"] + p["a3"] * c2, 0.0],
                     [p["a2"] + p["a3"] * c2, p["a2"], 0.0],
                     [0.0, 0.0, p["ir1"]]])


# The torques: T1 drives the motor (row 3), T2 joint 2 (row 2).
INPUT = np.array([[0.0, 0.0], [0.0, 1.0], [1.0, 0.0]])


def forces(p, q, qd, u):
    """r(q, q', u) of eq. (4.1) without the friction (cancelled by the observer, eq. (4.4))."""
    q1, q2, th = q
    s2 = math.sin(q2)
    return np.array([p["a3"] * qd[1] * (2 * qd[0] + qd[1]) * s2 + p["k1"] * (th - q1),
                     -p["bv2"] * qd[1] - p["a3"] * qd[0] ** 2 * s2,
                     -p["bv1"] * qd[2] + p["k1"] * (q1 - th)]) + INPUT @ u


def linearize(p, alpha, rest):
    """x' = A x + B u with the constraint 0 = C x + D u, at rest (zero speeds, theta = q1).

    x = (q1, q2, theta, q1', q2', theta', w1, w2): the angles, their speeds and the law's
    integrators w_i' = alpha_i^3 (q_i - q_di), eq. (4.2). The constraint is eq. (4.3):
    (q_i'' - q_di'') + 3 alpha_i (q_i' - q_di') + 3 alpha_i^2 (q_i - q_di) + w_i = 0, with q''
    from the equations of motion (the DAE in (x, u) has index 3).
    """
    k1 = p["k1"]
    dr_dq = np.array([[-k1, 0.0, k1], [0.0, 0.0, 0.0], [k1, 0.0, -k1]])
    dr_dqd = np.diag([0.0, -p["bv2"], -p["bv1"]])
    m_inv = np.linalg.inv(mass_matrix(p, rest[1]))
    a = np.zeros((8, 8))
    b = np.zeros((8, 2))
    a[0:3, 3:6] = np.eye(3)
    a[3:6, 0:3] = m_inv @ dr_dq
    a[3:6, 3:6] = m_inv @ dr_dqd
    b[3:6, :] = m_inv @ INPUT
    c = np.zeros((2, 8))
    d = np.zeros((2, 2))
    for i, al in enumerate(alpha):
        a[6 + i, i] = al ** 3
        c[i, :] = a[3 + i, :]
        c[i, 3 + i] += 3 * al
        c[i, i] += 3 * al ** 2
        c[i, 6 + i] += 1.0
        d[i, :] = b[3 + i, :]
    return a, b, c, d


# ------------------------------------------------------------- the predictor, eq. (2.4)
def pencil(lin, gain):
    """E z' = F z for z = (x, v), with u = K_pr x + v folded in (the controller designs v)."""
    a, b, c, d = lin
    f = np.zeros((10, 10))
    f[0:8, 0:8] = a + b @ gain
    f[0:8, 8:10] = b
    f[8:10, 0:8] = c + d @ gain
    f[8:10, 8:10] = d
    e = np.diag([1.0] * 8 + [0.0, 0.0])
    return e, f


def backward_euler(e, f, eps):
    """One step z_j -> z_{j+1} = (E - eps F)^-1 E z_j."""
    return np.linalg.solve(e - eps * f, e)


def predictor_gain(lin, gain):
    """V_k = K_pred x(t_n): k steps from (x, 0); only the last torque is used."""
    e, f = pencil(lin, gain)
    sweep = np.linalg.matrix_power(backward_euler(e, f, EPS), K)
    return sweep[8:10, 0:8]


# ------------------------------------------------------------------ the sampled loop
def loop_matrix(arm_lin, model_lin, gain):
    """The one-period map of zeta = (x(t_n), v held on [t_n, t_n+1)).

    Over one period the arm moves as x' = (A + B K_pr) x + B v (K_pr continuous), and the v
    computed from x(t_n) is held over the NEXT period: v_{n+1} = K_pred x_n (Fig. 2.1).
    """
    a, b, _, _ = arm_lin
    a_plant = a + b @ gain if INNER == "continuous" else a
    aug = np.zeros((10, 10))
    aug[0:8, 0:8] = a_plant * DELTA
    aug[0:8, 8:10] = b * DELTA
    transition = expm(aug)
    phi, gamma = transition[0:8, 0:8], transition[0:8, 8:10]
    if INNER == "sampled":
        phi = phi + gamma @ gain
    loop = np.zeros((10, 10))
    loop[0:8, 0:8] = phi
    loop[0:8, 8:10] = gamma
    loop[8:10, 0:8] = predictor_gain(model_lin, gain)
    return loop


# ---------------------------------------------------------- the digital loop (sensors on)
def is_digital(sensors):
    """True if the controller reads something other than the true state (a torque limit alone
    leaves the paper's loop)."""
    return (sensors["encoder"] > 0 or sensors["noise"] > 0 or sensors["velocity"] == "difference"
            or sensors["velocity_filter"] > 0)


def angle_variance(sensors):
    """The variance of one measured angle's error taken as white noise: q^2/12 + sigma^2, where
    q = 2 pi / N is the encoder's count (its rounding error is uniform over one count while the
    angle moves over many counts between samples) and sigma the noise's standard deviation."""
    q = 2 * math.pi / sensors["encoder"] if sensors["encoder"] > 0 else 0.0
    return q * q / 12 + sensors["noise"] ** 2


def digital_loop(arm_lin, model_lin, gain, velocity, velocity_filter):
    """The digital controller's loop at rest: zeta_{n+1} = F zeta_n + G eta_n, u_n = H zeta_n + J eta_n.

    The computer reads, at each t_n, only the angles, with an error eta_n (the encoder's rounding,
    the noise), and everything it computes is held until t_{n+1} (deviations from rest):

      m_n = q_n + eta_n                        the measured angles, q = (q1, q2, theta)
      r_n = q'_n, or (m_n - m_{n-1}) / delta   the raw velocities: exact, or differenced
      nu_n = beta nu_{n-1} + (1 - beta) r_n    through the low-pass filter, beta = exp(-delta/tau_v)
                                               (beta = 0 without it)
      X_n = (m_n, nu_n, w_n)                   what the controller knows (8 numbers)
      u_n = v_n + K_pr X_n                     the torque, held on [t_n, t_{n+1}) (K_pr held too:
                                               an analog K_pr would need analog velocities)
      v_{n+1} = K_pred X_n                     the prediction, applied one period later (Fig. 2.1)
      w_{n+1} = w_n + delta alpha^3 m_n[0:2]   the integrators, now the controller's own states
      p_{n+1} = Phi_p p_n + Gamma_p u_n        the arm's six states p = (q, q'), u held (zero-order hold)
      mprev_{n+1} = m_n                        kept for the difference
      nuprev_{n+1} = nu_n                      kept for the filter

    so zeta = (p, w, v, mprev, nuprev) has 6 + 2 + 2 + 3 + 3 = 16 states (with exact velocities
    nobody reads mprev, without a filter nobody reads nuprev: their eigenvalues are 0). Phi_p, Gamma_p come from the arm, K_pred from the arm the
    controller assumes. INNER plays no part: the preliminary feedback is always held here.
    Returns F, G, H, J.
    """
    a, b, _, _ = arm_lin
    # Zero-order hold: e^([A_p B_p; 0 0] delta) = [Phi_p Gamma_p; 0 I], A_p, B_p the arm's rows
    # of q and q' (they do not read w).
    aug = np.zeros((8, 8))
    aug[0:6, 0:6] = a[0:6, 0:6] * DELTA
    aug[0:6, 6:8] = b[0:6, :] * DELTA
    transition = expm(aug)
    phi_p, gamma_p = transition[0:6, 0:6], transition[0:6, 6:8]
    k_pred = predictor_gain(model_lin, gain)

    # X_n = S zeta_n + T eta_n.
    s = np.zeros((8, 16))
    t = np.zeros((8, 3))
    s[0:3, 0:3] = np.eye(3)  # m_n = q_n + eta_n
    t[0:3, 0:3] = np.eye(3)
    beta = math.exp(-DELTA / velocity_filter) if velocity_filter > 0 else 0.0
    if velocity == "difference":
        s[3:6, 0:3] = (1 - beta) * np.eye(3) / DELTA  # r_n = (q_n + eta_n - mprev_n) / delta
        s[3:6, 10:13] = -(1 - beta) * np.eye(3) / DELTA
        t[3:6, 0:3] = (1 - beta) * np.eye(3) / DELTA
    else:
        s[3:6, 3:6] = (1 - beta) * np.eye(3)  # r_n = q'_n
    s[3:6, 13:16] = beta * np.eye(3)  # nu_n = beta nuprev_n + (1 - beta) r_n
    s[6:8, 6:8] = np.eye(2)  # w_n

    # u_n = v_n + K_pr X_n = H zeta_n + J eta_n.
    h = gain @ s
    h[:, 8:10] += np.eye(2)
    j = gain @ t

    f = np.zeros((16, 16))
    g = np.zeros((16, 3))
    f[0:6, :] = gamma_p @ h  # p_{n+1} = Phi_p p_n + Gamma_p u_n
    f[0:6, 0:6] += phi_p
    g[0:6, :] = gamma_p @ j
    for i in range(2):  # w_{n+1} = w_n + delta alpha_i^3 m_n,i
        gain_w = DELTA * ALPHA[i] ** 3
        f[6 + i, 6 + i] = 1.0
        f[6 + i, :] += gain_w * s[i, :]
        g[6 + i, :] += gain_w * t[i, :]
    f[8:10, :] = k_pred @ s  # v_{n+1} = K_pred X_n
    g[8:10, :] = k_pred @ t
    f[10:13, :] = s[0:3, :]  # mprev_{n+1} = m_n
    g[10:13, :] = t[0:3, :]
    f[13:16, :] = s[3:6, :]  # nuprev_{n+1} = nu_n
    g[13:16, :] = t[3:6, :]
    return f, g, h, j


def noise_floor(f, g, h, j, sensors):
    """The stationary rms errors and torques the angles' white error leaves, at the instants t_n.

    With eta_n white of covariance r I (r = q^2/12 + sigma^2), the covariance P of zeta obeys
    P = F P F^T + r G G^T (the discrete Lyapunov equation; a solution only if rho < 1), and
    u_n = H zeta_n + J eta_n has covariance H P H^T + r J J^T. One solve with r = 1 serves every
    encoder and noise level: each rms is then scaled by sqrt(r).
    """
    p = solve_discrete_lyapunov(f, g @ g.T)
    torque = h @ p @ h.T + j @ j.T
    sd = math.sqrt(angle_variance(sensors))
    return {
        "rms_error": [sd * math.sqrt(max(p[i, i], 0.0)) for i in range(2)],  # e1, e2 (rad)
        "rms_torque": [sd * math.sqrt(max(torque[i, i], 0.0)) for i in range(2)],  # T1, T2 (N m)
    }


# --------------------------------------------------------------- the limit as delta -> 0
def limit_pair(arm_lin, model_lin, gain):
    """A4: what the loop tends to as delta -> 0 (section 3).

    Backward Euler forgets the DAE's inconsistent start after three steps, so a few steps at a
    small eps have the range and kernel of the limit projector Pi; purifying X <- X^2 (3 - 2X)
    gives Pi, and K_lim x is the v-part of Pi (x, 0). K_lim has no gain on theta, theta': the
    controller keeps six poles at -alpha and leaves the motor's pair, A4.
    """
    e, f = pencil(model_lin, gain)
    eps = 0.1 / max(ALPHA[0], ALPHA[1], 1e-3)
    x = np.linalg.matrix_power(backward_euler(e, f, eps), 4)
    for _ in range(60):
        nxt = 3 * x @ x - 2 * x @ x @ x
        done = np.abs(nxt - x).max() <= 1e-13 * max(np.abs(nxt).max(), 1.0)
        x = nxt
        if done:
            break
    k_lim = x[8:10, 0:8]
    a, b, _, _ = arm_lin
    closed = a + b @ (gain + k_lim)
    if MODEL == ARM:
        # The pair on the quotient R^8 / V*, in the motor's coordinates (rows theta, theta').
        complement = np.eye(8) - x[0:8, 0:8]
        coordinates = complement[[2, 5], :]
        projected = coordinates @ closed
        a4 = projected[:, [2, 5]]
        pair = np.linalg.eigvals(a4)
    else:
        # With a model error no quotient separates it: the fastest-swinging pair of all eight.
        ev = np.linalg.eigvals(closed)
        swinging = [l for l in ev if l.imag > 1e-9 * abs(l)]
        pair = [max(swinging, key=lambda l: l.imag)] if swinging else sorted(ev, key=lambda l: -l.real)[:2]
        if swinging:
            pair.append(pair[0].conjugate())
    pair = sorted(pair, key=lambda l: -l.imag)
    return [[float(l.real), float(l.imag)] for l in pair]


# ------------------------------------------------------------- the nonlinear loop, --simulate
def reference(t):
    """q_d, q_d', q_d'' of the slew: the 9th-order rest-to-rest polynomial of section 5."""
    start, end, tf = np.array(SLEW[0]), np.array(SLEW[1]), SLEW[2]
    tau = min(max(t / tf, 0.0), 1.0)
    s = tau ** 5 * (126 + tau * (-420 + tau * (540 + tau * (-315 + tau * 70))))
    ds = tau ** 4 * (630 + tau * (-2520 + tau * (3780 + tau * (-2520 + tau * 630))))
    dds = tau ** 3 * (2520 + tau * (-12600 + tau * (22680 + tau * (-17640 + tau * 5040))))
    span = end - start
    return start + span * s, span * ds / tf, span * dds / tf ** 2


def predict(x0, t0, guess):
    """U_k from X_0 = x(t_n): k backward-Euler steps of eq. (2.4), each solved by Newton."""
    p = MODEL
    q, qd, w = x0[0:3].copy(), x0[3:6].copy(), x0[6:8].copy()
    z = np.concatenate([qd, guess])
    for j in range(K):
        tj = t0 + (j + 1) * EPS
        r_q, r_qd, r_qdd = reference(tj)

        def residual(z):
            vn, u = z[0:3], z[3:5]
            qn = q + EPS * vn
            acc = (vn - qd) / EPS
            wn = w + EPS * np.array(ALPHA) ** 3 * (qn[0:2] - r_q)
            dyn = mass_matrix(p, qn[1]) @ acc - forces(p, qn, vn, u)
            law = (acc[0:2] - r_qdd) + 3 * np.array(ALPHA) * (vn[0:2] - r_qd) \
                + 3 * np.array(ALPHA) ** 2 * (qn[0:2] - r_q) + wn
            return np.concatenate([dyn, law])

        for _ in range(30):
            f0 = residual(z)
            jac = np.empty((5, 5))
            for i in range(5):
                h = 1e-7 * (1 + abs(z[i]))
                zi = z.copy()
                zi[i] += h
                jac[:, i] = (residual(zi) - f0) / h
            dz = np.linalg.solve(jac, f0)
            z = z - dz
            if np.max(np.abs(dz) / (1 + np.abs(z))) < 1e-10:
                break
        vn = z[0:3]
        q = q + EPS * vn
        w = w + EPS * np.array(ALPHA) ** 3 * (q[0:2] - r_q)
        qd = vn
    return z[3:5], np.concatenate([q, qd, w])


def simulate(duration):
    """The closed loop of Fig. 2.1: RK4 steps of at most 1 ms, the torque held one period late."""
    steps = max(1, math.ceil(DELTA / 1e-3))
    h = DELTA / steps
    q0, _, _ = reference(0.0)
    x = np.array([q0[0], q0[1], q0[0], 0, 0, 0, 0, 0], dtype=float)
    v_now, v_next, guess = np.zeros(2), np.zeros(2), np.zeros(2)
    times, errors = [], []

    def rates(t, x, v):
        q, qd = x[0:3], x[3:6]
        u = v + (K_PR @ x if INNER == "continuous" else held_feedback)
        acc = np.linalg.solve(mass_matrix(ARM, q[1]), forces(ARM, q, qd, u))
        return np.concatenate([qd, acc, np.array(ALPHA) ** 3 * (q[0:2] - reference(t)[0])])

    t = 0.0
    for n in range(int(round(duration / DELTA))):
        # At t_n: measure, predict; this torque is held from t_{n+1} on.
        v_now = v_next
        held_feedback = K_PR @ x
        u_k, x_k = predict(x, t, guess)
        guess = u_k
        v_next = u_k - K_PR @ x_k
        for _ in range(steps):
            k1 = rates(t, x, v_now)
            k2 = rates(t + h / 2, x + h / 2 * k1, v_now)
            k3 = rates(t + h / 2, x + h / 2 * k2, v_now)
            k4 = rates(t + h, x + h * k3, v_now)
            x = x + h / 6 * (k1 + 2 * k2 + 2 * k3 + k4)
            t += h
        e = x[0:2] - reference(t)[0]
        times.append(t)
        errors.append(e)
        if not np.all(np.isfinite(e)) or np.max(np.abs(e)) > math.pi:
            break
    return np.array(times), np.array(errors)


# Where the plot goes without a display or --plot; matplotlib's backends that only write files.
DEFAULT_PLOT = "flexarm_errors.png"
NON_INTERACTIVE = ("agg", "cairo", "pdf", "pgf", "ps", "svg", "template")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--simulate", action="store_true", help="run the nonlinear closed loop too")
    parser.add_argument("--duration", type=float, default=5.0, help="simulated seconds (with --simulate)")
    parser.add_argument("--plot", metavar="FILE.png",
                        help="save the errors' plot to FILE (implies --simulate; default: a window if there is "
                             f"a display, else {DEFAULT_PLOT})")
    args = parser.parse_args()
    if args.plot:
        args.simulate = True

    arm_lin = linearize(ARM, ALPHA, REST)
    model_lin = linearize(MODEL, ALPHA, REST)
    digital = is_digital(SENSORS)
    if digital:
        f, g, h, j = digital_loop(arm_lin, model_lin, K_PR, SENSORS["velocity"], SENSORS["velocity_filter"])
        loop = f
    else:
        loop = loop_matrix(arm_lin, model_lin, K_PR)
    eigenvalues = sorted(np.linalg.eigvals(loop), key=lambda l: (-abs(l), -l.imag))
    rho = float(abs(eigenvalues[0]))
    pair_open = limit_pair(arm_lin, model_lin, np.zeros((2, 8)))
    pair = limit_pair(arm_lin, model_lin, K_PR)

    print(f"delta = {DELTA} s, alpha = {ALPHA} 1/s, k = {K}, eps = delta/{M} = {EPS:.4g} s")
    if digital:
        print(f"sensors: encoder {SENSORS['encoder']:g} counts/rev, noise {SENSORS['noise']:g} rad, velocities "
              f"{SENSORS['velocity']} (filter tau_v = {SENSORS['velocity_filter']:g} s): the digital "
              "controller's loop (16 states)")
    print(f"spectral radius rho = {rho:.6f}: {'stable' if rho < 1 else 'unstable'}"
          f" (the errors change e-fold every {abs(DELTA / math.log(rho)):.3g} s)" if rho != 1 else "")
    print("eigenvalues of the one-period map (lambda, and s = ln(lambda)/delta in 1/s):")
    for l in eigenvalues:
        s = complex(np.log(l)) / DELTA if abs(l) > 0 else complex(float("nan"))
        print(f"  {l.real:+.6f} {l.imag:+.6f}j   |lambda| = {abs(l):.6f}   s = {s.real:+.4f} {s.imag:+.4f}j")
    print(f"A4 (delta -> 0) without K_pr: {pair_open[0][0]:+.4f} +/- {abs(pair_open[0][1]):.4f}j 1/s")
    print(f"A4 with this preliminary feedback: {pair[0][0]:+.4f} +/- {abs(pair[0][1]):.4f}j 1/s")
    floor = None
    if digital and rho < 1:
        floor = noise_floor(f, g, h, j, SENSORS)
        print("noise floor (white quantization noise of variance q^2/12 + sigma^2): "
              f"rms e1 = {floor['rms_error'][0]:.3g} rad, e2 = {floor['rms_error'][1]:.3g} rad; "
              f"rms T1 = {floor['rms_torque'][0]:.3g} N m, T2 = {floor['rms_torque'][1]:.3g} N m")
    elif digital:
        print("noise floor: none (the digital loop is unstable, rho >= 1)")

    result = {
        "state": "{{STATE}}",
        "spectral_radius": rho,
        "growth_rate": math.log(rho) / DELTA if rho > 0 else None,
        "eigenvalues": [[float(l.real), float(l.imag)] for l in eigenvalues],
        "limit_pair_open": pair_open,
        "limit_pair": pair,
        "noise_floor": floor,
    }
    if args.simulate:
        if digital or SENSORS["torque_limit"] > 0:
            print("(the simulation here runs the paper's perfect sensors, without the encoder, the noise, the "
                  "differenced velocities, their filter or the torque limit: flexarm's own simulation has them)")
        times, errors = simulate(args.duration)
        result["simulated_seconds"] = float(times[-1]) if len(times) else 0.0
        result["max_error"] = [float(v) for v in np.max(np.abs(errors), axis=0)] if len(times) else None
        try:
            import matplotlib
            import matplotlib.pyplot as plt
        except ImportError:
            print("(matplotlib is not installed: no plot)")
        else:
            fig, axes = plt.subplots(2, 1, sharex=True)
            for i, ax in enumerate(axes):
                ax.plot(times, errors[:, i])
                ax.set_ylabel(f"e{i + 1} [rad]")
            axes[1].set_xlabel("t [s]")
            axes[0].set_title("flexarm: {{STATE}}", fontsize=7)
            # Without a display matplotlib falls back to a backend that draws only into files
            # (Agg): plt.show() would then show nothing, so the plot is saved and said where.
            shown = not args.plot and matplotlib.get_backend().lower() not in NON_INTERACTIVE
            if shown:
                plt.show()
            else:
                path = args.plot or DEFAULT_PLOT
                fig.savefig(path, dpi=150, bbox_inches="tight")
                print(f"saved the plot of the errors to {os.path.abspath(path)}")
                result["plot"] = os.path.abspath(path)
    print(json.dumps(result))


if __name__ == "__main__":
    main()
