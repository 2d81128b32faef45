//! Which construction builds the smooth surface from K: the report's vertex-indexed PPS
//! (Ch. 4–5), the tutorial's (σ, v)-indexed PPS (seed 002, Parts IV–V; SPEC `SV-…`) or the
//! manifold spline F(M) (seed 003, Secs. 5.5–5.6; SPEC `MS-…`). One value, chosen once where a
//! command or an oracle session is dispatched (`oracle::choice` builds it).

/// The construction of the smooth surface.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, serde::Serialize, clap::ValueEnum)]
#[serde(rename_all = "kebab-case")]
pub enum Construction {
    /// The report's PPS: one chart per vertex of K (Ch. 4–5).
    #[default]
    Vertex,
    /// The tutorial's PPS: one chart per (σ, v), σ a triangle and v one of its vertices.
    SigmaV,
    /// The manifold spline of Gu–He–Qin (Secs. 5.5–5.6): f64 eval only (no MPFR, no jets).
    ManifoldSpline,
}

impl Construction {
    /// The name used on the command line, in the oracle protocol and in reports.
    pub fn name(self) -> &'static str {
        match self {
            Construction::Vertex => "vertex",
            Construction::SigmaV => "sigma-v",
            Construction::ManifoldSpline => "manifold-spline",
        }
    }
    /// Inverse of [`Construction::name`].
    pub fn parse(s: &str) -> Option<Construction> {
        match s {
            "vertex" => Some(Construction::Vertex),
            "sigma-v" => Some(Construction::SigmaV),
            "manifold-spline" => Some(Construction::ManifoldSpline),
            _ => None,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use clap::ValueEnum;

    #[test]
    fn names_parse_back_and_match_clap_and_serde() {
        for c in Construction::value_variants() {
            assert_eq!(Construction::parse(c.name()), Some(*c));
            let pv = c.to_possible_value().map(|p| p.get_name().to_string());
            assert_eq!(pv.as_deref(), Some(c.name()));
            let js = serde_json::to_string(c).unwrap_or_default();
            assert_eq!(js, format!("\"{}\"", c.name()));
        }
        assert_eq!(Construction::parse("sigma_v"), None);
    }
}
