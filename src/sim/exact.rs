// PLACEHOLDER: replaced by the exact branch at merge
//! Reference solution of the wall phase (placeholder with the agreed API; the `exact` branch
//! replaces this file). Method: the energy integral θ̇² = θ̇0² + 4ω²(sin²(θ/2) − sin²(θ0/2))
//! with the substitution sin(θ/2) = a cosh u (or a sinh u, or eᵘ) turns t(θ) into
//! ∫ du / (ω cos(θ/2)), a smooth integrand, summed by composite Gauss-Legendre quadrature.

/// The state where the wall force reaches zero.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Separation {
    /// θ_s, rad.
    pub angle: f64,
    /// t_s, s.
    pub time: f64,
    /// θ̇ at t_s, rad/s.
    pub rate: f64,
}

#[derive(Clone, Copy, Debug, PartialEq)]
enum Branch {
    Cosh(f64),
    Sinh(f64),
    Exp,
}

/// The wall-phase motion from (θ0, θ̇0).
#[derive(Clone, Debug)]
pub struct PhaseOne {
    omega: f64,
    branch: Branch,
    u0: f64,
    nodes: Vec<(f64, f64)>,
    separation: Option<Separation>,
}

fn gauss_legendre(n: usize) -> Vec<(f64, f64)> {
    (1..=n)
        .map(|i| {
            let mut x = (std::f64::consts::PI * (i as f64 - 0.25) / (n as f64 + 0.5)).cos();
            let mut dp = 1.0;
            for _ in 0..100 {
                let (mut p0, mut p1) = (1.0, x);
                for k in 2..=n {
                    let p2 = ((2 * k - 1) as f64 * x * p1 - (k - 1) as f64 * p0) / k as f64;
                    p0 = p1;
                    p1 = p2;
                }
                dp = n as f64 * (x * p1 - p0) / (x * x - 1.0);
                let dx = p1 / dp;
                x -= dx;
                if dx.abs() < 1e-17 {
                    break;
                }
            }
            (x, 2.0 / ((1.0 - x * x) * dp * dp))
        })
        .collect()
}

impl PhaseOne {
    /// theta0 in [0, π/2), rate0 >= 0, omega2 = 3g/(4l) > 0.
    pub fn new(theta0: f64, rate0: f64, omega2: f64) -> Result<PhaseOne, String> {
        if !(0.0..std::f64::consts::FRAC_PI_2).contains(&theta0)
            || rate0.is_nan()
            || rate0 < 0.0
            || omega2.is_nan()
            || omega2 <= 0.0
        {
            return Err(format!(
                "bad start: θ0 = {theta0}, θ̇0 = {rate0}, ω² = {omega2}"
            ));
        }
        let omega = omega2.sqrt();
        let s0 = (theta0 / 2.0).sin();
        let k2 = s0 * s0 - rate0 * rate0 / (4.0 * omega2);
        let (branch, u0) = if k2 > 0.0 {
            let a = k2.sqrt();
            (Branch::Cosh(a), (s0 / a).max(1.0).acosh())
        } else if k2 < 0.0 {
            let a = (-k2).sqrt();
            (Branch::Sinh(a), (s0 / a).asinh())
        } else {
            (
                Branch::Exp,
                if s0 > 0.0 { s0.ln() } else { f64::NEG_INFINITY },
            )
        };
        let mut p = PhaseOne {
            omega,
            branch,
            u0,
            nodes: gauss_legendre(20),
            separation: None,
        };
        if theta0 == 0.0 && rate0 == 0.0 {
            return Ok(p);
        }
        let cs = (2.0 * omega2 * theta0.cos() + rate0 * rate0) / (3.0 * omega2);
        if cs < 1.0 {
            let angle = cs.acos();
            let time = p.time_of(angle);
            p.separation = Some(Separation {
                angle,
                time,
                rate: p.rate_at_u(p.u_of(angle)),
            });
        }
        Ok(p)
    }

    /// None when the ladder never leaves the wall (θ0 = θ̇0 = 0: equilibrium).
    pub fn separation(&self) -> Option<Separation> {
        self.separation
    }

    fn half_sine(&self, u: f64) -> f64 {
        match self.branch {
            Branch::Cosh(a) => a * u.cosh(),
            Branch::Sinh(a) => a * u.sinh(),
            Branch::Exp => u.exp(),
        }
    }

    fn rate_at_u(&self, u: f64) -> f64 {
        2.0 * self.omega
            * match self.branch {
                Branch::Cosh(a) => a * u.sinh(),
                Branch::Sinh(a) => a * u.cosh(),
                Branch::Exp => u.exp(),
            }
    }

    fn u_of(&self, theta: f64) -> f64 {
        let s = (theta / 2.0).sin();
        match self.branch {
            Branch::Cosh(a) => (s / a).max(1.0).acosh(),
            Branch::Sinh(a) => (s / a).asinh(),
            Branch::Exp => s.ln(),
        }
    }

    fn integrand(&self, u: f64) -> f64 {
        let s = self.half_sine(u);
        1.0 / (self.omega * (1.0 - s * s).sqrt())
    }

    fn time_between(&self, u0: f64, u1: f64) -> f64 {
        let panels = ((u1 - u0).abs() / 0.25).ceil().max(1.0) as usize;
        let w = (u1 - u0) / panels as f64;
        let mut sum = 0.0;
        for p in 0..panels {
            let mid = u0 + (p as f64 + 0.5) * w;
            for &(x, wt) in &self.nodes {
                sum += wt * self.integrand(mid + 0.5 * w * x);
            }
        }
        0.5 * w * sum
    }

    fn time_of(&self, theta: f64) -> f64 {
        self.time_between(self.u0, self.u_of(theta))
    }

    fn u_at(&self, t: f64) -> f64 {
        // Newton on T(u) = t; dT/du is the integrand.
        let mut u = self.u0 + t * self.omega;
        if let Some(sep) = self.separation {
            u = u.min(self.u_of(sep.angle));
        }
        for _ in 0..60 {
            let du = (self.time_between(self.u0, u) - t) / self.integrand(u);
            u -= du;
            if du.abs() <= 1e-16 * u.abs().max(1.0) {
                break;
            }
        }
        u
    }

    /// θ(t) for 0 <= t <= separation time.
    pub fn theta(&self, t: f64) -> f64 {
        if self.separation.is_none() {
            return 0.0;
        }
        2.0 * self.half_sine(self.u_at(t)).min(1.0).asin()
    }

    /// θ̇(t) for 0 <= t <= separation time.
    pub fn rate(&self, t: f64) -> f64 {
        if self.separation.is_none() {
            return 0.0;
        }
        self.rate_at_u(self.u_at(t))
    }
}
