//! `pseudomanifold._native`: the PyO3 layer over the `pseudomanifold` crate (docs/python.md).
//!
//! Nothing here computes a quantity of the paper: every call goes to the crate's public API
//! (validator, `Pps`, S′, the oracle `Session`, `cli::check::check_report`, the certify
//! driver). This file converts arrays, releases the GIL around the work (which runs on the
//! crate's rayon pool) and maps every Rust error to a typed Python exception of
//! `pseudomanifold.errors`. Reports cross the border as the same serde JSON the CLI prints.

use numpy::ndarray::Array2;
use numpy::{IntoPyArray, PyArray1, PyArray2, PyReadonlyArray1, PyReadonlyArray2};
use pseudomanifold::certify::{
    all_configs, merge, read_certificate, run_with, shard, summary_table, write_certificate,
    write_text, Certificate, CertifyError, Model, Settings,
};
use pseudomanifold::cli::check::{check_report, CheckError};
use pseudomanifold::mesh::io::{read_mesh, ReadOptions};
use pseudomanifold::mesh::validate::validate;
use pseudomanifold::mesh::{FaceId, Location, MeshError, RawMesh, SimplicialSurface};
use pseudomanifold::oracle::protocol::{Request, Response, Session};
use pseudomanifold::surface::jet::Jet2;
use pseudomanifold::surface::output::{sample_surface_with, Attributes, SampledMesh};
use pseudomanifold::surface::sigma_v::SigmaVPps;
use pseudomanifold::surface::{Consts, PnTriangles, Pps, PpsOptions, Profile, SPrime, SurfaceKind};
use pyo3::prelude::*;
use pyo3::IntoPyObjectExt;
use rayon::prelude::*;
use serde_json::{json, Value};
use std::path::PathBuf;
use std::sync::Mutex;

// ---------------------------------------------------------------------------------------------
// Errors: the classes live in Python (pseudomanifold/errors.py) so that they can be caught and
// subclassed like any Python exception; here they are instantiated with their attributes.
// ---------------------------------------------------------------------------------------------

fn py_error(py: Python<'_>, class: &str, msg: String, attrs: &[(&str, PyObject)]) -> PyErr {
    let made = py
        .import("pseudomanifold.errors")
        .and_then(|m| m.getattr(class))
        .and_then(|c| c.call1((msg,)));
    match made {
        Ok(e) => {
            for (k, v) in attrs {
                if let Err(err) = e.setattr(*k, v) {
                    return err;
                }
            }
            PyErr::from_value(e)
        }
        Err(e) => e,
    }
}

/// Any convertible value as a Python object (None if the conversion fails: attributes of an
/// exception are best effort, the message carries everything).
fn obj<'py, T: IntoPyObject<'py>>(py: Python<'py>, x: T) -> PyObject {
    x.into_py_any(py).unwrap_or_else(|_| py.None())
}

fn err_simple(class: &'static str, msg: impl Into<String>) -> PyErr {
    let msg = msg.into();
    Python::with_gil(|py| py_error(py, class, msg, &[]))
}

/// A JSON value as Python data (through `json.loads`: the report's exact serde form).
fn json_to_py(py: Python<'_>, v: &Value) -> PyResult<PyObject> {
    let s =
        serde_json::to_string(v).map_err(|e| err_simple("PseudomanifoldError", e.to_string()))?;
    Ok(py.import("json")?.call_method1("loads", (s,))?.unbind())
}

fn mesh_error(e: &MeshError) -> PyErr {
    let (kind, path, at) = match e {
        MeshError::Io { path, .. } => ("io", path, None),
        MeshError::UnknownFormat { path } => ("unknown_format", path, None),
        MeshError::Parse { path, at, .. } => ("parse", path, Some(at)),
        MeshError::Encoding { path, at } => ("encoding", path, Some(at)),
        MeshError::Truncated { path, at, .. } => ("truncated", path, Some(at)),
        MeshError::TooLarge { path, at, .. } => ("too_large", path, Some(at)),
        MeshError::NotTriangle { path, at, .. } => ("not_triangle", path, Some(at)),
        MeshError::CannotTriangulate { path, at, .. } => ("cannot_triangulate", path, Some(at)),
        MeshError::TooFewSides { path, at, .. } => ("too_few_sides", path, Some(at)),
        MeshError::Empty { path } => ("empty", path, None),
        MeshError::Write { path, .. } => ("write", path, None),
    };
    let (line, byte, element) = match at {
        Some(Location::Line(l)) => (Some(*l), None, None),
        Some(Location::Byte(b)) => (None, Some(*b), None),
        Some(Location::Element { kind, index }) => (None, None, Some((kind.to_string(), *index))),
        _ => (None, None, None),
    };
    Python::with_gil(|py| {
        let attrs: Vec<(&str, PyObject)> = vec![
            ("kind", obj(py, kind)),
            ("file", obj(py, path.display().to_string())),
            ("line", obj(py, line)),
            ("byte", obj(py, byte)),
            ("element", obj(py, element)),
        ];
        py_error(py, "MeshError", e.to_string(), &attrs)
    })
}

fn certify_error(e: CertifyError) -> PyErr {
    err_simple("CertifyError", e.to_string())
}

fn json_error(e: serde_json::Error) -> PyErr {
    err_simple("PseudomanifoldError", format!("JSON: {e}"))
}

/// Validate `raw` (Sec. 3.1, the crate's validator, exactly): the surface, or a
/// `ValidationError` carrying the failing check IDs, their witnesses and the whole report.
fn validated(py: Python<'_>, raw: &RawMesh) -> PyResult<(SimplicialSurface, Value)> {
    let v = py.allow_threads(|| validate(raw));
    let report = serde_json::to_value(&v.report).map_err(json_error)?;
    match v.surface {
        Some(k) => Ok((k, report)),
        None => {
            let failing: Vec<&pseudomanifold::report::CheckResult> =
                v.report.checks.iter().filter(|c| c.failed()).collect();
            let ids: Vec<String> = failing.iter().map(|c| c.id.clone()).collect();
            let witnesses: Value = failing
                .iter()
                .map(|c| (c.id.clone(), json!(c.witnesses)))
                .collect::<serde_json::Map<String, Value>>()
                .into();
            let classes: Vec<&str> = v.report.error_classes.iter().map(|c| c.name()).collect();
            let src = raw
                .source
                .as_ref()
                .map_or("<arrays>".to_string(), |p| p.display().to_string());
            let msg = format!(
                "{src} is not a simplicial surface (Sec. 3.1): failing checks {}; defect classes {}",
                ids.join(", "),
                classes.join(", ")
            );
            let attrs: Vec<(&str, PyObject)> = vec![
                ("checks", ids.into_py_any(py)?),
                ("witnesses", json_to_py(py, &witnesses)?),
                ("classes", classes.into_py_any(py)?),
                ("report", json_to_py(py, &report)?),
            ];
            Err(py_error(py, "ValidationError", msg, &attrs))
        }
    }
}

// ---------------------------------------------------------------------------------------------
// K: a validated simplicial surface.
// ---------------------------------------------------------------------------------------------

/// A triangle mesh validated as a simplicial surface K (Sec. 3.1, Defs. 3.1.1–3.1.6).
#[pyclass(frozen, module = "pseudomanifold._native")]
struct Surface {
    raw: RawMesh,
    k: SimplicialSurface,
    report: Value,
}

#[pymethods]
impl Surface {
    /// Surface(V, F): V float64 (n, 3), F int64 (m, 3) (0-based). Indices outside 0..2³²−1
    /// are passed to the validator as 2³²−1 so that it reports them (D3.1.3(i)).
    #[new]
    fn new(py: Python<'_>, v: PyReadonlyArray2<f64>, f: PyReadonlyArray2<i64>) -> PyResult<Self> {
        let (va, fa) = (v.as_array(), f.as_array());
        if va.ncols() != 3 || fa.ncols() != 3 {
            return Err(err_simple(
                "UsageError",
                format!(
                    "V must be (n, 3) and F (m, 3); got {:?} and {:?}",
                    va.shape(),
                    fa.shape()
                ),
            ));
        }
        let positions: Vec<[f64; 3]> = va.rows().into_iter().map(|r| [r[0], r[1], r[2]]).collect();
        let faces: Vec<[u32; 3]> = fa
            .rows()
            .into_iter()
            .map(|r| [r[0], r[1], r[2]].map(|i| u32::try_from(i).unwrap_or(u32::MAX)))
            .collect();
        let raw = RawMesh::from_arrays(positions, faces);
        let (k, report) = validated(py, &raw)?;
        Ok(Surface { raw, k, report })
    }

    /// Number of vertices of K.
    #[getter]
    fn num_vertices(&self) -> usize {
        self.k.num_vertices()
    }

    /// Number of triangles of K.
    #[getter]
    fn num_faces(&self) -> usize {
        self.k.num_faces()
    }

    /// The vertex positions as stored (n, 3).
    #[getter]
    fn vertices<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray2<f64>>> {
        rows3(py, self.raw.positions.iter().copied())
    }

    /// The triangles as stored (m, 3), 0-based.
    #[getter]
    fn faces<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray2<i64>>> {
        let n = self.raw.faces.len();
        let flat: Vec<i64> = self
            .raw
            .faces
            .iter()
            .flat_map(|f| f.map(i64::from))
            .collect();
        let a = Array2::from_shape_vec((n, 3), flat)
            .map_err(|e| err_simple("PseudomanifoldError", e.to_string()))?;
        Ok(a.into_pyarray(py))
    }

    /// The validator's report (Sec. 3.1) as Python data (the JSON of `ppm check --json`).
    fn validation_report(&self, py: Python<'_>) -> PyResult<PyObject> {
        json_to_py(py, &self.report)
    }

    /// `ppm check [--labels] [--spec FLAGS]` on this mesh: the report's JSON and whether the
    /// command would exit 0.
    #[pyo3(signature = (spec, labels, flags))]
    fn check_json(
        &self,
        py: Python<'_>,
        spec: bool,
        labels: bool,
        flags: Vec<String>,
    ) -> PyResult<(String, bool)> {
        check_raw(py, &self.raw, spec, labels, flags)
    }
}

fn rows3<'py>(
    py: Python<'py>,
    it: impl Iterator<Item = [f64; 3]>,
) -> PyResult<Bound<'py, PyArray2<f64>>> {
    let flat: Vec<f64> = it.flat_map(|p| p).collect();
    let n = flat.len() / 3;
    let a = Array2::from_shape_vec((n, 3), flat)
        .map_err(|e| err_simple("PseudomanifoldError", e.to_string()))?;
    Ok(a.into_pyarray(py))
}

fn check_raw(
    py: Python<'_>,
    raw: &RawMesh,
    spec: bool,
    labels: bool,
    flags: Vec<String>,
) -> PyResult<(String, bool)> {
    let args = pseudomanifold::cli::parse_check_spec_args(flags)
        .map_err(|e| err_simple("UsageError", e))?;
    if args.construction != pseudomanifold::surface::Construction::Vertex {
        return Err(err_simple(
            "UsageError",
            "check(): only the vertex construction (ppm check --spec --construction sigma-v is CLI-only)",
        ));
    }
    let rep = py
        .allow_threads(|| check_report(raw, labels, spec.then_some(&args), false))
        .map_err(|e| match e {
            CheckError::Usage(m) => err_simple("UsageError", m),
            CheckError::Certificate(c) => certify_error(c),
        })?;
    let ok = rep.passes();
    let s = serde_json::to_string_pretty(&rep).map_err(json_error)?;
    Ok((s, ok))
}

/// Read a mesh file (OFF, OBJ, PLY) and validate it.
#[pyfunction]
#[pyo3(signature = (path, triangulate=false))]
fn load(py: Python<'_>, path: PathBuf, triangulate: bool) -> PyResult<Surface> {
    let opts = ReadOptions {
        triangulate,
        ..ReadOptions::default()
    };
    let raw = py
        .allow_threads(|| read_mesh(&path, &opts))
        .map_err(|e| mesh_error(&e))?;
    let (k, report) = validated(py, &raw)?;
    Ok(Surface { raw, k, report })
}

/// `ppm check FILE [--spec FLAGS]` as a library call: (report JSON, passes).
#[pyfunction]
#[pyo3(signature = (path, spec, labels, flags, triangulate=false))]
fn check_file(
    py: Python<'_>,
    path: PathBuf,
    spec: bool,
    labels: bool,
    flags: Vec<String>,
    triangulate: bool,
) -> PyResult<(String, bool)> {
    let opts = ReadOptions {
        triangulate,
        ..ReadOptions::default()
    };
    let raw = py
        .allow_threads(|| read_mesh(&path, &opts))
        .map_err(|e| mesh_error(&e))?;
    check_raw(py, &raw, spec, labels, flags)
}

// ---------------------------------------------------------------------------------------------
// The vertex PPS (Chapter 5, Sec. 6.1.4) and its S′.
// ---------------------------------------------------------------------------------------------

fn surface_error(e: impl std::fmt::Display, at: Option<(usize, u32, [f64; 3])>) -> PyErr {
    Python::with_gil(|py| {
        let mut attrs: Vec<(&str, PyObject)> = Vec::new();
        if let Some((i, f, b)) = at {
            attrs.push(("index", obj(py, i)));
            attrs.push(("face", obj(py, f)));
            attrs.push(("bary", obj(py, b.to_vec())));
        }
        let msg = match at {
            Some((i, f, b)) => format!("point {i} (face {f}, bary {b:?}): {e}"),
            None => e.to_string(),
        };
        py_error(py, "EvalError", msg, &attrs)
    })
}

fn points(
    faces: &PyReadonlyArray1<i64>,
    bary: &PyReadonlyArray2<f64>,
) -> PyResult<Vec<(u32, [f64; 3])>> {
    let (f, b) = (faces.as_array(), bary.as_array());
    if b.ncols() != 3 || b.nrows() != f.len() {
        return Err(err_simple(
            "UsageError",
            format!(
                "faces must be (n,) and bary (n, 3); got {:?} and {:?}",
                f.shape(),
                b.shape()
            ),
        ));
    }
    // A face id outside u32 is no face of K: passed on as 2³²−1, which the border query
    // answers with NoSuchFace (API-ids).
    Ok(f.iter()
        .zip(b.rows())
        .map(|(&f, r)| (u32::try_from(f).unwrap_or(u32::MAX), [r[0], r[1], r[2]]))
        .collect())
}

fn first_error<T, E: std::fmt::Display>(
    results: Vec<Result<T, E>>,
    pts: &[(u32, [f64; 3])],
) -> PyResult<Vec<T>> {
    let mut out = Vec::with_capacity(results.len());
    for (i, r) in results.into_iter().enumerate() {
        match r {
            Ok(x) => out.push(x),
            Err(e) => return Err(surface_error(e, Some((i, pts[i].0, pts[i].1)))),
        }
    }
    Ok(out)
}

/// The parametric pseudo-surface of Chapter 5 built over S′ (Sec. 5.1, 6.2).
#[pyclass(frozen, module = "pseudomanifold._native")]
struct PpsHandle {
    pps: Pps,
    target: SPrime,
    jet2: Consts<Jet2<f64>>,
}

#[pymethods]
impl PpsHandle {
    /// Build ψ_v for every vertex (Sec. 5.2) over S′ = `sprime` (pn | loop) with `profile`
    /// (paper | authors-code).
    #[new]
    #[pyo3(signature = (surface, sprime="pn", profile="paper"))]
    fn new(py: Python<'_>, surface: &Surface, sprime: &str, profile: &str) -> PyResult<Self> {
        let kind = SurfaceKind::parse(sprime).ok_or_else(|| {
            err_simple(
                "UsageError",
                format!("sprime {sprime:?}: expected pn or loop"),
            )
        })?;
        let profile = Profile::parse(profile).ok_or_else(|| {
            err_simple(
                "UsageError",
                format!("profile {profile:?}: expected paper or authors-code"),
            )
        })?;
        let k = &surface.k;
        py.allow_threads(|| {
            let target = SPrime::for_profile(kind, k, profile)
                .map_err(|e| format!("S′ = {}: {e}", kind.name()))?;
            let pps = Pps::try_build(
                k,
                target.as_target(),
                PpsOptions {
                    profile,
                    ..PpsOptions::default()
                },
            )
            .map_err(|e| e.to_string())?;
            let jet2 = pps.consts(53);
            Ok::<_, String>(PpsHandle { pps, target, jet2 })
        })
        .map_err(|e| err_simple("BuildError", e))
    }

    /// eval(σ, λ, μ, ν) of Sec. 6.1.4 at every point, with the normal and curvatures from
    /// the analytic derivatives of θ_v (order-2 jets) unless `attributes` is "positions"
    /// (plain f64 eval, Pps::eval_batch_f64). Returns (positions, normals, gaussian, mean).
    #[pyo3(signature = (faces, bary, attributes="curvature"))]
    #[allow(clippy::type_complexity)]
    fn eval<'py>(
        &self,
        py: Python<'py>,
        faces: PyReadonlyArray1<i64>,
        bary: PyReadonlyArray2<f64>,
        attributes: &str,
    ) -> PyResult<(
        Bound<'py, PyArray2<f64>>,
        Option<Bound<'py, PyArray2<f64>>>,
        Option<Bound<'py, PyArray1<f64>>>,
        Option<Bound<'py, PyArray1<f64>>>,
    )> {
        let pts = points(&faces, &bary)?;
        match attributes {
            "positions" => {
                let batch: Vec<(FaceId, [f64; 3])> =
                    pts.iter().map(|&(f, b)| (FaceId(f), b)).collect();
                let res = py.allow_threads(|| self.pps.eval_batch_f64(&batch));
                let pos = first_error(res, &pts)?;
                Ok((rows3(py, pos.into_iter())?, None, None, None))
            }
            "curvature" => {
                let res: Vec<_> = py.allow_threads(|| {
                    pts.par_iter()
                        .map(|&(f, b)| {
                            self.pps
                                .eval_geometry_of_order(FaceId(f), b, &self.jet2)
                                .map(|x| x.2)
                        })
                        .collect()
                });
                let g = first_error(res, &pts)?;
                let pos = rows3(py, g.iter().map(|s| s.point))?;
                let nrm = rows3(py, g.iter().map(|s| s.normal))?;
                let gauss = PyArray1::from_vec(py, g.iter().map(|s| s.gaussian).collect());
                let mean = PyArray1::from_vec(py, g.iter().map(|s| s.mean).collect());
                Ok((pos, Some(nrm), Some(gauss), Some(mean)))
            }
            other => Err(err_simple(
                "UsageError",
                format!("attributes {other:?}: expected curvature or positions"),
            )),
        }
    }

    /// S′ at every point (Sec. 5.1: the PN triangle b_σ, or the Loop limit surface).
    fn eval_sprime<'py>(
        &self,
        py: Python<'py>,
        faces: PyReadonlyArray1<i64>,
        bary: PyReadonlyArray2<f64>,
    ) -> PyResult<Bound<'py, PyArray2<f64>>> {
        let pts = points(&faces, &bary)?;
        let t = self.target.as_target();
        let res: Vec<Result<[f64; 3], pseudomanifold::surface::SurfaceError>> =
            py.allow_threads(|| {
                pts.par_iter()
                    .map(|&(f, b)| {
                        pseudomanifold::surface::eval::check_barycentric(b)?;
                        let corners = self.pps.face(FaceId(f))?;
                        Ok(t.eval(FaceId(f), corners, b))
                    })
                    .collect()
            });
        let pos = first_error(res, &pts)?;
        rows3(py, pos.into_iter())
    }

    /// Sec. 6.2: M sampled by midpoint subdivision at `level`: (V, F, normals, gaussian, mean).
    #[allow(clippy::type_complexity)]
    fn sample<'py>(
        &self,
        py: Python<'py>,
        level: u32,
    ) -> PyResult<(
        Bound<'py, PyArray2<f64>>,
        Bound<'py, PyArray2<i64>>,
        Bound<'py, PyArray2<f64>>,
        Bound<'py, PyArray1<f64>>,
        Bound<'py, PyArray1<f64>>,
    )> {
        let m = py
            .allow_threads(|| sample_surface_with(&self.pps, level, Attributes::Curvature, None))
            .map_err(|e| surface_error(e, None))?;
        sampled(py, m)
    }

    /// Number of faces of K.
    #[getter]
    fn num_faces(&self) -> usize {
        self.pps.num_faces()
    }

    /// The profile's name (paper | authors-code).
    #[getter]
    fn profile(&self) -> &'static str {
        self.pps.options.profile.name()
    }

    /// S′'s name.
    #[getter]
    fn sprime(&self) -> &'static str {
        self.target.kind().name()
    }
}

#[allow(clippy::type_complexity)]
fn sampled(
    py: Python<'_>,
    m: SampledMesh,
) -> PyResult<(
    Bound<'_, PyArray2<f64>>,
    Bound<'_, PyArray2<i64>>,
    Bound<'_, PyArray2<f64>>,
    Bound<'_, PyArray1<f64>>,
    Bound<'_, PyArray1<f64>>,
)> {
    let nf = m.faces.len();
    let flat: Vec<i64> = m.faces.iter().flat_map(|f| f.map(i64::from)).collect();
    let f = Array2::from_shape_vec((nf, 3), flat)
        .map_err(|e| err_simple("PseudomanifoldError", e.to_string()))?
        .into_pyarray(py);
    Ok((
        rows3(py, m.positions.into_iter())?,
        f,
        rows3(py, m.normals.into_iter())?,
        PyArray1::from_vec(py, m.gaussian),
        PyArray1::from_vec(py, m.mean),
    ))
}

/// The tutorial's (σ, v)-indexed PPS (SPEC SV-…): 3·n_t p-domains, S′ = PN triangles.
#[pyclass(frozen, module = "pseudomanifold._native")]
struct SigmaVHandle {
    pps: SigmaVPps,
}

#[pymethods]
impl SigmaVHandle {
    /// Build it with κ (SV-D3) and the patch degree (SV-D11).
    #[new]
    #[pyo3(signature = (surface, kappa=pseudomanifold::surface::sigma_v::DEFAULT_KAPPA, patch_degree=pseudomanifold::surface::sigma_v::DEFAULT_PATCH_DEGREE))]
    fn new(py: Python<'_>, surface: &Surface, kappa: f64, patch_degree: usize) -> PyResult<Self> {
        let k = &surface.k;
        if !(1..=pseudomanifold::surface::sigma_v::patch::MAX_PATCH_DEGREE).contains(&patch_degree)
        {
            return Err(err_simple(
                "UsageError",
                format!("patch_degree {patch_degree}: expected 1..=15"),
            ));
        }
        py.allow_threads(|| {
            let pn = PnTriangles::new(k);
            SigmaVPps::build(k, &pn, kappa, patch_degree).map_err(|e| e.to_string())
        })
        .map(|pps| SigmaVHandle { pps })
        .map_err(|e| err_simple("BuildError", e))
    }

    /// A fitted surface written by `ppm fit -o` (seed 002 adaptive fitting, SPEC
    /// AF-format-roundtrip): the (σ, v) PPS over its base mesh, read bit-exactly.
    #[staticmethod]
    fn from_fit(py: Python<'_>, path: std::path::PathBuf) -> PyResult<Self> {
        py.allow_threads(|| {
            pseudomanifold::fitting::format::read_fit(&path).map_err(|e| e.to_string())
        })
        .map(|f| SigmaVHandle { pps: f.pps })
        .map_err(|e| err_simple("MeshError", e))
    }

    /// eval (SV-D13) in f64 at every point: positions (n, 3).
    fn eval<'py>(
        &self,
        py: Python<'py>,
        faces: PyReadonlyArray1<i64>,
        bary: PyReadonlyArray2<f64>,
    ) -> PyResult<Bound<'py, PyArray2<f64>>> {
        let pts = points(&faces, &bary)?;
        let res: Vec<_> = py.allow_threads(|| {
            pts.par_iter()
                .map(|&(f, b)| self.pps.eval_f64(FaceId(f), b))
                .collect()
        });
        let pos = first_error(res, &pts)?;
        rows3(py, pos.into_iter())
    }

    /// Sampled by midpoint subdivision at `level`: (V, F, normals, gaussian, mean).
    #[allow(clippy::type_complexity)]
    fn sample<'py>(
        &self,
        py: Python<'py>,
        level: u32,
    ) -> PyResult<(
        Bound<'py, PyArray2<f64>>,
        Bound<'py, PyArray2<i64>>,
        Bound<'py, PyArray2<f64>>,
        Bound<'py, PyArray1<f64>>,
        Bound<'py, PyArray1<f64>>,
    )> {
        let m = py
            .allow_threads(|| self.pps.sample_surface(level))
            .map_err(|e| surface_error(e, None))?;
        sampled(py, m)
    }
}

// ---------------------------------------------------------------------------------------------
// The oracle (docs/oracle.md): one Session, the same Request/Response types as `ppm oracle`.
// ---------------------------------------------------------------------------------------------

#[pyclass(frozen, module = "pseudomanifold._native")]
struct OracleHandle {
    session: Mutex<Session>,
}

/// One row of a batched answer: ok, value (decimal strings), f64, difference, error, info.
type Row = (
    bool,
    Vec<String>,
    Vec<Option<f64>>,
    Option<f64>,
    Option<(String, String)>,
    Option<String>,
);

fn as_strings(v: &Option<Value>) -> Vec<String> {
    match v {
        Some(Value::Array(a)) => a
            .iter()
            .map(|x| match x {
                Value::String(s) => s.clone(),
                other => other.to_string(),
            })
            .collect(),
        Some(Value::String(s)) => vec![s.clone()],
        Some(other) => vec![other.to_string()],
        None => vec![],
    }
}

fn as_floats(v: &Option<Value>) -> Vec<Option<f64>> {
    let one = |x: &Value| match x {
        Value::Bool(b) => Some(if *b { 1.0 } else { 0.0 }),
        other => other.as_f64(),
    };
    match v {
        Some(Value::Array(a)) => a.iter().map(one).collect(),
        Some(x) => vec![one(x)],
        None => vec![],
    }
}

fn row(r: Result<Response, String>) -> Row {
    match r {
        Ok(r) if r.ok => (
            true,
            as_strings(&r.value),
            as_floats(&r.f64),
            r.difference,
            None,
            r.info.map(|i| i.to_string()),
        ),
        Ok(r) => {
            let e = r.error.unwrap_or(Value::Null);
            let kind = e
                .get("kind")
                .and_then(Value::as_str)
                .unwrap_or("error")
                .to_string();
            let msg = e
                .get("message")
                .and_then(Value::as_str)
                .unwrap_or("")
                .to_string();
            (false, vec![], vec![], None, Some((kind, msg)), None)
        }
        Err(m) => (
            false,
            vec![],
            vec![],
            None,
            Some(("malformed".into(), m)),
            None,
        ),
    }
}

#[pymethods]
impl OracleHandle {
    /// A session on K (Session::with_surface) at `bits`, with `profile` and S′.
    #[new]
    #[pyo3(signature = (surface, bits=256, profile="paper", sprime="pn"))]
    fn new(surface: &Surface, bits: u32, profile: &str, sprime: &str) -> PyResult<Self> {
        let mut s = Session::with_surface(surface.k.clone());
        for req in [
            Request::SetPrecision { bits },
            Request::SetProfile {
                profile: profile.to_string(),
            },
            Request::SetSurface {
                surface: sprime.to_string(),
            },
        ] {
            s.handle(&req)
                .map_err(|e| err_simple("UsageError", e.to_string()))?;
        }
        Ok(OracleHandle {
            session: Mutex::new(s),
        })
    }

    /// One protocol line, answered exactly as `ppm oracle` answers it.
    fn handle_line(&self, py: Python<'_>, line: String) -> PyResult<String> {
        let r = py.allow_threads(|| {
            let mut s = self
                .session
                .lock()
                .map_err(|_| "session poisoned".to_string())?;
            let resp = s.handle_line(&line);
            serde_json::to_string(&resp).map_err(|e| e.to_string())
        });
        r.map_err(|e| err_simple("OracleError", e))
    }

    /// Many requests of one op: `requests` are JSON objects without "op" (one per point);
    /// each is parsed as a protocol Request (the same validation) and answered in turn.
    fn batch(&self, py: Python<'_>, op: String, requests: Vec<String>) -> PyResult<Vec<Row>> {
        py.allow_threads(|| {
            let mut s = self
                .session
                .lock()
                .map_err(|_| "session poisoned".to_string())?;
            Ok::<_, String>(
                requests
                    .iter()
                    .map(|body| {
                        let req = serde_json::from_str::<Value>(body)
                            .map_err(|e| e.to_string())
                            .and_then(|mut v| {
                                if let Some(o) = v.as_object_mut() {
                                    o.insert("op".into(), Value::String(op.clone()));
                                }
                                serde_json::from_value::<Request>(v).map_err(|e| e.to_string())
                            });
                        row(req.and_then(|q| match s.handle(&q) {
                            Ok(r) => Ok(r),
                            Err(e) => Ok(Response::error(&e)),
                        }))
                    })
                    .collect(),
            )
        })
        .map_err(|e| err_simple("OracleError", e))
    }

    /// The precision of the MPFR values, in bits.
    #[getter]
    fn bits(&self) -> PyResult<u32> {
        let s = self
            .session
            .lock()
            .map_err(|_| err_simple("OracleError", "session poisoned"))?;
        Ok(s.bits())
    }
}

// ---------------------------------------------------------------------------------------------
// Certification (src/certify): shards, merge, files, exactly as `ppm certify`.
// ---------------------------------------------------------------------------------------------

fn cert_json(c: &Certificate) -> PyResult<String> {
    serde_json::to_string(c).map_err(json_error)
}

fn cert_parse(s: &str) -> PyResult<Certificate> {
    serde_json::from_str(s).map_err(json_error)
}

/// Number of degree configurations up to `max_degree` (certify::all_configs).
#[pyfunction]
fn certify_config_count(max_degree: u32) -> usize {
    all_configs(max_degree).len()
}

/// `ppm certify --max-degree M --jobs J [--shard K/N]`: the certificate as JSON (not
/// compacted). `shard` None proves every configuration.
#[pyfunction]
#[pyo3(signature = (max_degree, shard_k_n=None, jobs=2))]
fn certify_shard(
    py: Python<'_>,
    max_degree: u32,
    shard_k_n: Option<(usize, usize)>,
    jobs: usize,
) -> PyResult<String> {
    if !(3..=64).contains(&max_degree) {
        return Err(certify_error(CertifyError::BadArg(format!(
            "--max-degree {max_degree} (3..=64)"
        ))));
    }
    if let Some((k, n)) = shard_k_n {
        if k == 0 || n == 0 || k > n {
            return Err(certify_error(CertifyError::BadArg(format!(
                "--shard {k}/{n}: expected K/N with 1 ≤ K ≤ N"
            ))));
        }
    }
    let cert = py.allow_threads(|| {
        let all = all_configs(max_degree);
        let configs = match shard_k_n {
            Some((k, n)) => shard(&all, k, n),
            None => all,
        };
        run_with(
            &configs,
            max_degree,
            &Model::paper(),
            &Settings::default(),
            jobs,
            shard_k_n,
            None,
        )
    });
    cert_json(&cert.map_err(certify_error)?)
}

/// `ppm certify merge`: join shard certificates (JSON) into one (JSON).
#[pyfunction]
fn certify_merge(py: Python<'_>, parts: Vec<String>) -> PyResult<String> {
    let parts = parts
        .iter()
        .map(|s| cert_parse(s))
        .collect::<PyResult<Vec<_>>>()?;
    let merged = py.allow_threads(|| merge(parts)).map_err(certify_error)?;
    cert_json(&merged)
}

/// Write the certificate file (compacted, as `ppm certify --out`) and, if given, the summary
/// (`--summary`); returns the summary table.
#[pyfunction]
#[pyo3(signature = (cert, out, summary=None))]
fn certify_write(cert: &str, out: PathBuf, summary: Option<PathBuf>) -> PyResult<String> {
    let c = cert_parse(cert)?;
    write_certificate(&c, &out).map_err(certify_error)?;
    let table = summary_table(&c);
    if let Some(p) = summary {
        write_text(&p, &table).map_err(certify_error)?;
    }
    Ok(table)
}

/// Read a certificate file (statements expanded) as JSON.
#[pyfunction]
fn certify_read(path: PathBuf) -> PyResult<String> {
    cert_json(&read_certificate(&path).map_err(certify_error)?)
}

// ---------------------------------------------------------------------------------------------
// The `ppm` command line itself (console script `ppm` of the package).
// ---------------------------------------------------------------------------------------------

/// Run `ppm ARGS...` (argv[0] is the program name); returns the exit status.
#[pyfunction]
fn ppm_main(py: Python<'_>, argv: Vec<String>) -> i32 {
    let code = py.allow_threads(|| pseudomanifold::cli::main_from(argv));
    // ExitCode has no stable accessor: find it among the statuses the commands use.
    (0..=255u8)
        .find(|&c| std::process::ExitCode::from(c) == code)
        .map_or(1, i32::from)
}

/// Threads of the crate's rayon pool (the global pool every parallel call uses).
#[pyfunction]
fn num_threads() -> usize {
    rayon::current_num_threads()
}

#[pymodule]
fn _native(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<Surface>()?;
    m.add_class::<PpsHandle>()?;
    m.add_class::<SigmaVHandle>()?;
    m.add_class::<OracleHandle>()?;
    m.add_function(wrap_pyfunction!(load, m)?)?;
    m.add_function(wrap_pyfunction!(check_file, m)?)?;
    m.add_function(wrap_pyfunction!(certify_config_count, m)?)?;
    m.add_function(wrap_pyfunction!(certify_shard, m)?)?;
    m.add_function(wrap_pyfunction!(certify_merge, m)?)?;
    m.add_function(wrap_pyfunction!(certify_write, m)?)?;
    m.add_function(wrap_pyfunction!(certify_read, m)?)?;
    m.add_function(wrap_pyfunction!(ppm_main, m)?)?;
    m.add_function(wrap_pyfunction!(num_threads, m)?)?;
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    Ok(())
}
