//! The configurations of Sec. 4.1 that every map of [`super::maps`] depends on: an oriented
//! edge `[u, w]` is an [`EdgeConfig`] (the degrees `m_u, m_w` and the labels `i = s_u(w)`,
//! `j = s_w(u)`, Def. 4.1.4), a triangle a [`TriangleConfig`], a pair of vertices a
//! [`VertexPair`] (Defs. 4.1.9/4.1.10). Each constructor validates degrees (≥ 3) and label
//! ranges, and a triangle's labels must come from a fan.

/// Why a configuration is invalid.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum ConfigError {
    /// A degree m < 3 ([`MIN_DEGREE`]); Chapter 4 assumes every vertex has degree at least three.
    #[error("degree {m} < 3 (Chapter 4 assumes every vertex has degree at least three)")]
    DegreeTooSmall {
        /// The offending degree.
        m: u32,
    },
    /// A label is not in 0..m.
    #[error("label {label} is not in 0..{m}")]
    LabelOutOfRange {
        /// The offending label.
        label: u32,
        /// The degree of the vertex whose star it labels.
        m: u32,
    },
    /// The six labels of a triangle do not step by +1 everywhere or by −1 everywhere (see
    /// [`TriangleConfig::orientation`]); the message gives the three steps.
    #[error("triangle labels are not consistent with one fan orientation: {0}")]
    NotAFan(String),
    /// A degree too large for the requested output (a figure draws all m gluing domains).
    #[error("degree {m} exceeds the limit {limit} of this output")]
    DegreeTooLarge {
        /// The offending degree.
        m: u32,
        /// The largest accepted degree.
        limit: u32,
    },
}

/// Smallest admissible degree (Chapter 4: "the degree of every vertex ... is at least three").
pub const MIN_DEGREE: u32 = 3;

/// The data an oriented edge `[u, w]` contributes to Chapter 4 (Sec. 6.1.3: "an expression
/// that depends only on the degrees m_u and m_w ... and on the identifiers of the half-edges").
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, serde::Serialize)]
pub struct EdgeConfig {
    /// m_u: degree of u.
    pub m_u: u32,
    /// i: the label s_u(w) = u'_i of w in u's star.
    pub i: u32,
    /// m_w: degree of w.
    pub m_w: u32,
    /// j: the label s_w(u) = w'_j of u in w's star.
    pub j: u32,
}

fn check_degree(m: u32) -> Result<(), ConfigError> {
    if m < MIN_DEGREE {
        Err(ConfigError::DegreeTooSmall { m })
    } else {
        Ok(())
    }
}
fn check_label(label: u32, m: u32) -> Result<(), ConfigError> {
    if label >= m {
        Err(ConfigError::LabelOutOfRange { label, m })
    } else {
        Ok(())
    }
}

impl EdgeConfig {
    /// Validating constructor: `m_u, m_w >= 3`, `i < m_u`, `j < m_w`.
    pub fn new(m_u: u32, i: u32, m_w: u32, j: u32) -> Result<Self, ConfigError> {
        check_degree(m_u)?;
        check_degree(m_w)?;
        check_label(i, m_u)?;
        check_label(j, m_w)?;
        Ok(EdgeConfig { m_u, i, m_w, j })
    }
    /// Re-validate (for values built with struct literals).
    pub fn validate(&self) -> Result<(), ConfigError> {
        EdgeConfig::new(self.m_u, self.i, self.m_w, self.j).map(|_| ())
    }
    /// The oriented edge `[w, u]`.
    pub fn reversed(&self) -> Self {
        EdgeConfig {
            m_u: self.m_w,
            i: self.j,
            m_w: self.m_u,
            j: self.i,
        }
    }
}

/// A triangle `[u, w, x]` of K seen from Chapter 4: degrees and the six labels.
/// Field `a_b` is the label `s_a(b)` of `b` in `a`'s star.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, serde::Serialize)]
pub struct TriangleConfig {
    /// m_u: degree of u.
    pub m_u: u32,
    /// m_w: degree of w.
    pub m_w: u32,
    /// m_x: degree of x.
    pub m_x: u32,
    /// s_u(w).
    pub u_w: u32,
    /// s_u(x).
    pub u_x: u32,
    /// s_w(u).
    pub w_u: u32,
    /// s_w(x).
    pub w_x: u32,
    /// s_x(u).
    pub x_u: u32,
    /// s_x(w).
    pub x_w: u32,
}

/// One vertex of a triangle `[u, w, x]` as its star sees the triangle (Def. 4.1.4): its degree
/// and the labels of the next and the previous vertex of the triangle (for u: s_u(w) and
/// s_u(x); for w: s_w(x) and s_w(u); for x: s_x(u) and s_x(w)). Named fields, so the nine
/// numbers of a triangle cannot be passed in the wrong order.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Corner {
    /// The vertex's degree m.
    pub m: u32,
    /// The label of the next vertex of the triangle in this vertex's star.
    pub next: u32,
    /// The label of the previous vertex of the triangle in this vertex's star.
    pub prev: u32,
}

/// Orientation of a triangle `[u, w, x]` w.r.t. the counterclockwise labellings.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
pub enum FanOrientation {
    /// s_u(x) = s_u(w)+1, s_w(u) = s_w(x)+1, s_x(w) = s_x(u)+1 (mod degrees).
    Ccw,
    /// The three differences are −1.
    Cw,
}

impl TriangleConfig {
    /// Validates degrees, label ranges, and that the labels come from a fan: in each vertex's
    /// star the other two vertices are adjacent (labels differ by ±1 mod degree), with one
    /// common orientation (as for a consistently oriented surface, cf. proof of L4.2.2).
    pub fn new(u: Corner, w: Corner, x: Corner) -> Result<Self, ConfigError> {
        let t = TriangleConfig {
            m_u: u.m,
            m_w: w.m,
            m_x: x.m,
            u_w: u.next,
            u_x: u.prev,
            w_u: w.prev,
            w_x: w.next,
            x_u: x.next,
            x_w: x.prev,
        };
        t.orientation().map(|_| t)
    }

    /// Build the triangle `[u, w, x]` in CCW orientation from degrees and the labels of `w`
    /// in `u`'s star, `x` in `w`'s star, `u` in `x`'s star (the other three follow).
    pub fn ccw(
        m_u: u32,
        m_w: u32,
        m_x: u32,
        u_w: u32,
        w_x: u32,
        x_u: u32,
    ) -> Result<Self, ConfigError> {
        check_degree(m_u)?;
        check_degree(m_w)?;
        check_degree(m_x)?;
        check_label(u_w, m_u)?;
        check_label(w_x, m_w)?;
        check_label(x_u, m_x)?;
        let ccw = |m: u32, next: u32| Corner {
            m,
            next,
            prev: (next + 1) % m,
        };
        TriangleConfig::new(ccw(m_u, u_w), ccw(m_w, w_x), ccw(m_x, x_u))
    }

    /// Validates degrees and label ranges, then the fan condition: in each star the other two
    /// vertices are adjacent (labels differ by ±1), all three in the same direction.
    pub fn orientation(&self) -> Result<FanOrientation, ConfigError> {
        for (m, a, b) in [
            (self.m_u, self.u_w, self.u_x),
            (self.m_w, self.w_u, self.w_x),
            (self.m_x, self.x_u, self.x_w),
        ] {
            check_degree(m)?;
            check_label(a, m)?;
            check_label(b, m)?;
        }
        let d = |m: u32, from: u32, to: u32| -> i64 {
            let diff = (to as i64 - from as i64).rem_euclid(m as i64);
            if diff == 1 {
                1
            } else if diff == m as i64 - 1 {
                -1
            } else {
                0
            }
        };
        let du = d(self.m_u, self.u_w, self.u_x);
        let dw = d(self.m_w, self.w_x, self.w_u);
        let dx = d(self.m_x, self.x_u, self.x_w);
        match (du, dw, dx) {
            (1, 1, 1) => Ok(FanOrientation::Ccw),
            (-1, -1, -1) => Ok(FanOrientation::Cw),
            _ => Err(ConfigError::NotAFan(format!(
                "steps s_u(w)->s_u(x) = {du}, s_w(x)->s_w(u) = {dw}, s_x(u)->s_x(w) = {dx} \
                 (each must be +1 for all or -1 for all)"
            ))),
        }
    }

    /// Oriented edge [u, w].
    pub fn uw(&self) -> EdgeConfig {
        EdgeConfig {
            m_u: self.m_u,
            i: self.u_w,
            m_w: self.m_w,
            j: self.w_u,
        }
    }
    /// Oriented edge [u, x].
    pub fn ux(&self) -> EdgeConfig {
        EdgeConfig {
            m_u: self.m_u,
            i: self.u_x,
            m_w: self.m_x,
            j: self.x_u,
        }
    }
    /// Oriented edge [w, x].
    pub fn wx(&self) -> EdgeConfig {
        EdgeConfig {
            m_u: self.m_w,
            i: self.w_x,
            m_w: self.m_x,
            j: self.x_w,
        }
    }
    /// Oriented edge [x, u].
    pub fn xu(&self) -> EdgeConfig {
        self.ux().reversed()
    }
    /// Oriented edge [x, w].
    pub fn xw(&self) -> EdgeConfig {
        self.wx().reversed()
    }
    /// Oriented edge [w, u].
    pub fn wu(&self) -> EdgeConfig {
        self.uw().reversed()
    }
}

/// The pair (u, w) of Defs. 4.1.9/4.1.10.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
pub enum VertexPair {
    /// u = w, of degree m.
    Same {
        /// m_u, the degree of u.
        m: u32,
    },
    /// [u, w] is an edge.
    Edge(EdgeConfig),
    /// u ≠ w and [u, w] is not an edge: Ω_uw = ∅.
    NotAdjacent,
}
