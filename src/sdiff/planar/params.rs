//! Parameter files (TOML) for a simplicial map on a planar complex, and the per-triangle maps
//! they define.
//!
//! Control points, weights and g's are keyed by *global* vertex ids, so two triangles sharing
//! a face share its parameters by construction (Mello–Velho Sec. 3: "adjacent simplexes …
//! share the same control parameters in its common face"); a `triangle = f` key overrides an
//! entry in one triangle only (how a planted disagreement is written). Numbers are exact:
//! `"p/q"`, decimal strings, integers, or TOML floats (taken as the exact double).
//!
//! ```toml
//! family = "polynomial"     # polynomial | rational | monotonic
//! degree = 3
//! [[control]]               # unlisted control points are fixed: c_I = Σ I_i v_i / n
//! at = [0, 1, 2]            # the multiset I of global vertex ids, |I| = degree
//! point = ["1/3", "1/4"]    # c_I in the plane
//! [[weight]]                # rational only; unlisted weights are 1
//! at = [0, 0, 1]
//! q = "2"
//! [[g]]                     # monotonic only; unlisted g are g(t) = t
//! vertex = 0
//! coeffs = ["0", "1", "1/2"]   # g(t) = Σ coeffs[k] t^k
//! [iso]                     # optional: f per vertex and the level c (Sec. 4)
//! f = ["-1", "1", "1"]
//! c = "0"
//! ```

use super::complex::PlanarComplex;
use super::maps::SimplexMap;
use crate::sdiff::common::params::{parse_spec, read_spec, FamilySpec, Multiset, ParamError, Spec};
use crate::sdiff::common::poly1::Poly1;
use crate::sdiff::common::poly2::multi_indices;
use std::path::Path;

/// Largest degree accepted (the exact engine costs O(n⁴) rationals per piece).
pub(crate) const MAX_DEGREE: usize = 12;

/// A parsed planar parameter file.
pub type MapSpec = Spec<2>;

/// Reads and parses a planar parameter file.
pub fn read(path: &Path) -> Result<MapSpec, ParamError> {
    read_spec(path, MAX_DEGREE)
}

/// Parses the text of a planar parameter file (`path` only names it in errors).
pub fn parse(text: &str, path: &Path) -> Result<MapSpec, ParamError> {
    parse_spec(text, path, MAX_DEGREE)
}

/// The per-triangle maps defined by a spec on a complex.
#[derive(Debug, Clone)]
pub struct ComplexMap {
    /// One map per triangle of the complex, in the triangle's vertex order.
    pub maps: Vec<SimplexMap>,
}

impl MapSpec {
    /// Checks the keys ([`Spec::check_keys`]); then builds the per-triangle maps.
    pub fn build(&self, k: &PlanarComplex, path: &Path) -> Result<ComplexMap, ParamError> {
        self.check_keys(path, k.points.len(), &k.triangles, "triangle")?;
        let maps = (0..k.triangles.len()).map(|f| self.map_of(k, f)).collect();
        Ok(ComplexMap { maps })
    }

    /// The global multiset of a local multi-index in triangle f.
    pub(crate) fn global_key(k: &PlanarComplex, f: usize, i: [usize; 3]) -> Multiset {
        let t = k.triangles[f];
        let mut m: Vec<u32> = (0..3)
            .flat_map(|c| std::iter::repeat(t[c]).take(i[c]))
            .collect();
        m.sort_unstable();
        m
    }

    fn map_of(&self, k: &PlanarComplex, f: usize) -> SimplexMap {
        match self.family {
            FamilySpec::Monotonic => {
                let t = k.triangles[f];
                let g = t.map(|v| self.g.get(&v).cloned().unwrap_or_else(Poly1::identity));
                SimplexMap::monotonic(g)
            }
            FamilySpec::Polynomial | FamilySpec::Rational => {
                let n = self.degree;
                let fixed = SimplexMap::fixed_control(n);
                let mut control = Vec::new();
                let mut weights = Vec::new();
                for (idx, i) in multi_indices(n).into_iter().enumerate() {
                    let key = Self::global_key(k, f, i);
                    let (c, w) = self.entry(f, key);
                    control.push(match c {
                        Some(p) => k.barycentric(f, p),
                        None => fixed[idx].clone(),
                    });
                    weights.push(w);
                }
                if self.family == FamilySpec::Polynomial {
                    SimplexMap::polynomial(n, control)
                } else {
                    SimplexMap::rational(n, control, weights)
                }
            }
        }
    }
}

impl MapSpec {
    /// The spec as a parameter file (exact numbers as "p/q" strings); reads back to the same
    /// spec with [`parse`].
    pub fn to_toml(&self) -> String {
        use std::fmt::Write;
        let mut s = String::new();
        let family = match self.family {
            FamilySpec::Monotonic => "monotonic",
            FamilySpec::Polynomial => "polynomial",
            FamilySpec::Rational => "rational",
        };
        let _ = writeln!(s, "family = \"{family}\"");
        if self.family != FamilySpec::Monotonic {
            let _ = writeln!(s, "degree = {}", self.degree);
        }
        let tri = |t: &Option<usize>| t.map(|f| format!("triangle = {f}\n")).unwrap_or_default();
        let mut control: Vec<_> = self.control.iter().collect();
        control.sort_by(|a, b| a.0.cmp(b.0));
        for ((t, m), p) in control {
            let _ = write!(
                s,
                "[[control]]\nat = {m:?}\npoint = [\"{}\", \"{}\"]\n{}",
                p[0],
                p[1],
                tri(t)
            );
        }
        let mut weights: Vec<_> = self.weights.iter().collect();
        weights.sort_by(|a, b| a.0.cmp(b.0));
        for ((t, m), w) in weights {
            let _ = write!(s, "[[weight]]\nat = {m:?}\nq = \"{w}\"\n{}", tri(t));
        }
        let mut g: Vec<_> = self.g.iter().collect();
        g.sort_by_key(|x| *x.0);
        for (v, p) in g {
            let cs: Vec<String> = p.0.iter().map(|c| format!("\"{c}\"")).collect();
            let _ = write!(s, "[[g]]\nvertex = {v}\ncoeffs = [{}]\n", cs.join(", "));
        }
        if let Some((f, c)) = &self.iso {
            let fs: Vec<String> = f.iter().map(|x| format!("\"{x}\"")).collect();
            let _ = write!(s, "[iso]\nf = [{}]\nc = \"{c}\"\n", fs.join(", "));
        }
        s
    }
}
