//! PLY reader (Greg Turk's polygon file format, <https://paulbourke.net/dataformats/ply/>).
//!
//! Supported subset:
//! * `format ascii 1.0`, `binary_little_endian 1.0`, `binary_big_endian 1.0`;
//! * header lines `comment`, `obj_info`, `element <name> <count>`,
//!   `property <type> <name>` and `property list <count type> <item type> <name>` with the
//!   types `char uchar short ushort int uint float double` and their aliases
//!   `int8 uint8 int16 uint16 int32 uint32 float32 float64`;
//! * element `vertex` with scalar properties `x`, `y`, `z` (any scalar type, converted to
//!   f64); element `face` with an integer list `vertex_indices` (or `vertex_index`), any
//!   integer count and index type. Every other property and element is skipped by its
//!   declared size. Elements may come in any order.
//! * ascii bodies: one element instance per line.
//!
//! Errors name the header line, the body line (ascii) or the element and its index (binary).
//! Fewer instances than declared is [`MeshError::Truncated`]; data after the last declared
//! element is a parse error.

use super::context::{capped_capacity, parse_coord, Ctx};
use super::polygon::FaceSink;
use super::text::Lines;
use crate::mesh::error::{Location, MeshError};
use crate::mesh::raw::{MeshFormat, RawMesh};

/// A PLY scalar type.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Scalar {
    I8,
    U8,
    I16,
    U16,
    I32,
    U32,
    F32,
    F64,
}

impl Scalar {
    fn from_name(s: &str) -> Option<Scalar> {
        Some(match s {
            "char" | "int8" => Scalar::I8,
            "uchar" | "uint8" => Scalar::U8,
            "short" | "int16" => Scalar::I16,
            "ushort" | "uint16" => Scalar::U16,
            "int" | "int32" => Scalar::I32,
            "uint" | "uint32" => Scalar::U32,
            "float" | "float32" => Scalar::F32,
            "double" | "float64" => Scalar::F64,
            _ => return None,
        })
    }

    fn size(self) -> usize {
        match self {
            Scalar::I8 | Scalar::U8 => 1,
            Scalar::I16 | Scalar::U16 => 2,
            Scalar::I32 | Scalar::U32 | Scalar::F32 => 4,
            Scalar::F64 => 8,
        }
    }

    fn is_int(self) -> bool {
        !matches!(self, Scalar::F32 | Scalar::F64)
    }
}

#[derive(Debug, Clone, Copy)]
enum Kind {
    Scalar(Scalar),
    List { count: Scalar, item: Scalar },
}

#[derive(Debug)]
struct Property {
    name: String,
    kind: Kind,
}

/// What a property of the vertex or face element is used for.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Role {
    Skip,
    Coord(usize),
    /// Index into [`VERTEX_SCALARS`].
    Kept(usize),
    Corners,
}

/// Vertex scalar properties kept besides x, y, z: the normals and curvatures that
/// `ppm sample` writes (read back by `ppm render --input-is-samples`).
pub(super) const VERTEX_SCALARS: [&str; 5] =
    ["nx", "ny", "nz", "gaussian_curvature", "mean_curvature"];

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum ElemKind {
    Vertex,
    Face,
    Other,
}

impl ElemKind {
    fn label(self) -> &'static str {
        match self {
            ElemKind::Vertex => "vertex",
            ElemKind::Face => "face",
            ElemKind::Other => "element",
        }
    }
}

#[derive(Debug)]
struct Element {
    name: String,
    count: u64,
    line: u64,
    kind: ElemKind,
    props: Vec<Property>,
    roles: Vec<Role>,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Encoding {
    Ascii,
    Le,
    Be,
}

/// If `bytes` starts with a `ply` magic line: the format named by its `format` line
/// (ascii if there is none).
pub(crate) fn sniff(bytes: &[u8]) -> Option<MeshFormat> {
    if !(bytes.starts_with(b"ply\n") || bytes.starts_with(b"ply\r\n")) {
        return None;
    }
    let head = &bytes[..bytes.len().min(65536)];
    let mut lines = Lines::new(head, 1);
    while let Some((_, Ok(s))) = lines.next_line() {
        let mut t = s.split_ascii_whitespace();
        match t.next() {
            Some("format") => {
                return Some(match t.next() {
                    Some("binary_little_endian") => MeshFormat::PlyBinaryLittleEndian,
                    Some("binary_big_endian") => MeshFormat::PlyBinaryBigEndian,
                    _ => MeshFormat::PlyAscii,
                })
            }
            Some("end_header") => break,
            _ => {}
        }
    }
    Some(MeshFormat::PlyAscii)
}

struct Header {
    encoding: Encoding,
    elements: Vec<Element>,
    /// Number of the `end_header` line.
    last_line: u64,
}

fn parse_header<'a>(ctx: &Ctx<'_>, lines: &mut Lines<'a>) -> Result<Header, MeshError> {
    match lines.next_line() {
        Some((_, Ok("ply"))) => {}
        Some((no, Err(_))) => return Err(ctx.encoding(Location::Line(no))),
        _ => return Err(ctx.parse(Location::Line(1), "expected the magic line 'ply'")),
    }
    let mut encoding = None;
    let mut elements: Vec<Element> = Vec::new();
    let lim = &ctx.opts.limits;
    loop {
        let (no, line) = lines.next_line().ok_or_else(|| {
            ctx.truncated(
                Location::Line(lines.line_no()),
                "header without 'end_header'",
            )
        })?;
        let s = line.map_err(|_| ctx.encoding(Location::Line(no)))?;
        let at = Location::Line(no);
        let mut t = s.split_ascii_whitespace();
        match t.next() {
            Some("end_header") => {
                let encoding =
                    encoding.ok_or_else(|| ctx.parse(at.clone(), "header has no 'format' line"))?;
                return Ok(Header {
                    encoding,
                    elements,
                    last_line: no,
                });
            }
            Some("comment") | Some("obj_info") | None => {}
            Some("format") => {
                if encoding.is_some() {
                    return Err(ctx.parse(at, "second 'format' line"));
                }
                encoding = Some(match t.next() {
                    Some("ascii") => Encoding::Ascii,
                    Some("binary_little_endian") => Encoding::Le,
                    Some("binary_big_endian") => Encoding::Be,
                    other => {
                        return Err(ctx.parse(
                            at,
                            format!("unknown PLY format '{}'", other.unwrap_or_default()),
                        ))
                    }
                });
                if t.next().is_none() {
                    return Err(ctx.parse(at, "'format' line without a version"));
                }
            }
            Some("element") => {
                let (Some(name), Some(count), None) = (t.next(), t.next(), t.next()) else {
                    return Err(ctx.parse(at, "expected 'element <name> <count>'"));
                };
                let count: u64 = count.parse().map_err(|_| {
                    ctx.parse(at.clone(), format!("invalid element count '{count}'"))
                })?;
                let kind = match name {
                    "vertex" => ElemKind::Vertex,
                    "face" => ElemKind::Face,
                    _ => ElemKind::Other,
                };
                if kind != ElemKind::Other && elements.iter().any(|e| e.kind == kind) {
                    return Err(ctx.parse(at, format!("second '{name}' element")));
                }
                let (what, limit) = match kind {
                    ElemKind::Vertex => ("vertex", lim.max_vertices),
                    ElemKind::Face => ("face", lim.max_faces),
                    ElemKind::Other => ("element", lim.max_other_elements),
                };
                ctx.check_limit(at, what, count, limit)?;
                elements.push(Element {
                    name: name.to_string(),
                    count,
                    line: no,
                    kind,
                    props: Vec::new(),
                    roles: Vec::new(),
                });
            }
            Some("property") => {
                let elem = elements
                    .last_mut()
                    .ok_or_else(|| ctx.parse(at.clone(), "'property' before any 'element'"))?;
                let ty = |name: &str| {
                    Scalar::from_name(name).ok_or_else(|| {
                        ctx.parse(at.clone(), format!("unknown property type '{name}'"))
                    })
                };
                let (kind, name) = match (t.next(), t.next(), t.next(), t.next(), t.next()) {
                    (Some("list"), Some(c), Some(i), Some(n), None) => {
                        let count = ty(c)?;
                        if !count.is_int() {
                            return Err(ctx.parse(
                                at,
                                format!("list count type '{c}' is not an integer type"),
                            ));
                        }
                        (
                            Kind::List {
                                count,
                                item: ty(i)?,
                            },
                            n,
                        )
                    }
                    (Some("list"), ..) => {
                        return Err(ctx.parse(
                            at,
                            "expected 'property list <count type> <item type> <name>'",
                        ))
                    }
                    (Some(s), Some(n), None, None, None) => (Kind::Scalar(ty(s)?), n),
                    _ => return Err(ctx.parse(at, "expected 'property <type> <name>'")),
                };
                if elem.props.iter().any(|p| p.name == name) {
                    return Err(ctx.parse(at, format!("second property '{name}'")));
                }
                let role = match (elem.kind, name, kind) {
                    (ElemKind::Vertex, "x" | "y" | "z", Kind::Scalar(_)) => {
                        Role::Coord(usize::from(name.as_bytes()[0] - b'x'))
                    }
                    (ElemKind::Vertex, "x" | "y" | "z", Kind::List { .. }) => {
                        return Err(ctx.parse(at, format!("vertex property '{name}' is a list")))
                    }
                    (ElemKind::Vertex, _, Kind::Scalar(_)) if VERTEX_SCALARS.contains(&name) => {
                        Role::Kept(VERTEX_SCALARS.iter().position(|&n| n == name).unwrap_or(0))
                    }
                    (
                        ElemKind::Face,
                        "vertex_indices" | "vertex_index",
                        Kind::List { item, .. },
                    ) => {
                        if !item.is_int() {
                            return Err(ctx.parse(
                                at,
                                format!("face property '{name}' has a non-integer item type"),
                            ));
                        }
                        if elem.roles.contains(&Role::Corners) {
                            return Err(ctx.parse(
                                at,
                                "face element has both 'vertex_indices' and 'vertex_index'",
                            ));
                        }
                        Role::Corners
                    }
                    (ElemKind::Face, "vertex_indices" | "vertex_index", Kind::Scalar(_)) => {
                        return Err(ctx.parse(at, format!("face property '{name}' is not a list")))
                    }
                    _ => Role::Skip,
                };
                elem.props.push(Property {
                    name: name.to_string(),
                    kind,
                });
                elem.roles.push(role);
            }
            Some(other) => {
                let other: String = other.chars().take(32).collect();
                return Err(ctx.parse(at, format!("unknown PLY header keyword '{other}'")));
            }
        }
    }
}

/// Checks that the vertex and face elements have what the reader needs.
fn check_roles(ctx: &Ctx<'_>, elements: &[Element]) -> Result<(), MeshError> {
    for e in elements {
        let at = Location::Line(e.line);
        match e.kind {
            ElemKind::Vertex => {
                for (axis, name) in ["x", "y", "z"].iter().enumerate() {
                    if !e.roles.contains(&Role::Coord(axis)) {
                        return Err(
                            ctx.parse(at, format!("vertex element has no property '{name}'"))
                        );
                    }
                }
            }
            ElemKind::Face => {
                if !e.roles.contains(&Role::Corners) {
                    return Err(ctx.parse(
                        at,
                        "face element has no list property 'vertex_indices' or 'vertex_index'",
                    ));
                }
            }
            ElemKind::Other => {}
        }
    }
    Ok(())
}

/// What the body readers fill in.
struct Body {
    positions: Vec<[f64; 3]>,
    /// Values of the [`VERTEX_SCALARS`] (filled only for those the header declares).
    kept: [Vec<f64>; 5],
    vertex_origin: Vec<u64>,
    sink: FaceSink,
}

pub(crate) fn read(bytes: &[u8], ctx: &Ctx<'_>) -> Result<RawMesh, MeshError> {
    if bytes.iter().all(|b| b.is_ascii_whitespace()) {
        return Ok(RawMesh::default());
    }
    let mut lines = Lines::new(bytes, 1);
    let header = parse_header(ctx, &mut lines)?;
    check_roles(ctx, &header.elements)?;
    let body_bytes = lines.remaining();
    let (min_v, min_f) = match header.encoding {
        Encoding::Ascii => (6, 8),
        _ => (1, 1),
    };
    let mut body = Body {
        kept: Default::default(),
        positions: Vec::new(),
        vertex_origin: Vec::new(),
        sink: FaceSink::new(ctx.opts.triangulate, 0),
    };
    for e in &header.elements {
        match e.kind {
            ElemKind::Vertex => {
                let cap = capped_capacity(e.count, body_bytes.len(), min_v);
                body.positions.reserve_exact(cap);
                body.vertex_origin.reserve_exact(cap);
            }
            ElemKind::Face => {
                body.sink = FaceSink::new(
                    ctx.opts.triangulate,
                    capped_capacity(e.count, body_bytes.len(), min_f),
                )
            }
            ElemKind::Other => {}
        }
    }
    let (format, origin_is_line) = match header.encoding {
        Encoding::Ascii => {
            let mut body_lines = Lines::new(body_bytes, header.last_line.saturating_add(1));
            read_ascii(ctx, &header.elements, &mut body_lines, &mut body)?;
            (MeshFormat::PlyAscii, true)
        }
        Encoding::Le | Encoding::Be => {
            let mut cur = Cursor {
                data: body_bytes,
                pos: 0,
                be: header.encoding == Encoding::Be,
            };
            let body_offset = bytes.len() - body_bytes.len();
            read_binary(ctx, &header.elements, &mut cur, body_offset, &mut body)?;
            let format = if cur.be {
                MeshFormat::PlyBinaryBigEndian
            } else {
                MeshFormat::PlyBinaryLittleEndian
            };
            (format, false)
        }
    };
    let faces = body.sink.finish(ctx, &body.positions, origin_is_line)?;
    let vertex_scalars = VERTEX_SCALARS
        .iter()
        .zip(std::mem::take(&mut body.kept))
        .filter(|(_, v)| !v.is_empty() && v.len() == body.positions.len())
        .map(|(n, v)| (n.to_string(), v))
        .collect();
    Ok(RawMesh {
        vertex_scalars,
        positions: body.positions,
        faces: faces.faces,
        face_origin: faces.origins,
        vertex_origin: body.vertex_origin,
        source: None,
        format: Some(format),
        triangulated_polygons: faces.triangulated_polygons,
        origin_is_line,
    })
}

/// Converts an ascii list item or count to a 0-based index / count.
fn ascii_uint(ctx: &Ctx<'_>, no: u64, tok: &str, what: &str) -> Result<u64, MeshError> {
    match tok.parse::<u64>() {
        Ok(v) => Ok(v),
        Err(_) if tok.parse::<i64>().is_ok() => {
            Err(ctx.parse(Location::Line(no), format!("negative {what} {tok}")))
        }
        Err(_) => Err(ctx.parse(Location::Line(no), format!("invalid {what} '{tok}'"))),
    }
}

fn read_ascii(
    ctx: &Ctx<'_>,
    elements: &[Element],
    lines: &mut Lines<'_>,
    body: &mut Body,
) -> Result<(), MeshError> {
    let mut idx: Vec<u32> = Vec::new();
    for e in elements {
        if e.props.is_empty() {
            continue;
        }
        for k in 0..e.count {
            let (no, s) = loop {
                match lines.next_line() {
                    None => {
                        return Err(ctx.truncated(
                            Location::Line(lines.line_no()),
                            format!(
                                "the file ends after {k} of {} declared '{}' elements",
                                e.count, e.name
                            ),
                        ))
                    }
                    Some((no, Err(_))) => return Err(ctx.encoding(Location::Line(no))),
                    Some((no, Ok(s))) if !s.trim().is_empty() => break (no, s),
                    Some(_) => {}
                }
            };
            let at = || Location::Line(no);
            let mut t = s.split_ascii_whitespace();
            let mut p = [0.0; 3];
            idx.clear();
            for (prop, role) in e.props.iter().zip(&e.roles) {
                let mut next = |what: &str| {
                    t.next().ok_or_else(|| {
                        ctx.parse(
                            at(),
                            format!("{} {k}: missing {what} of property '{}'", e.name, prop.name),
                        )
                    })
                };
                match prop.kind {
                    Kind::Scalar(sc) => {
                        let tok = next("the value")?;
                        let v = ascii_scalar(tok, sc).ok_or_else(|| {
                            ctx.parse(
                                at(),
                                format!(
                                    "{} {k}: invalid value '{tok}' for property '{}'",
                                    e.name, prop.name
                                ),
                            )
                        })?;
                        match role {
                            Role::Coord(axis) => {
                                if let Some(c) = p.get_mut(*axis) {
                                    *c = v;
                                }
                            }
                            Role::Kept(i) => body.kept[*i].push(v),
                            _ => {}
                        }
                    }
                    Kind::List { count, item } => {
                        let tok = next("the count")?;
                        let n = ascii_uint(ctx, no, tok, "list count")?;
                        if ascii_scalar(tok, count).is_none() {
                            return Err(ctx.parse(
                                at(),
                                format!("list count {n} does not fit the count type {count:?}"),
                            ));
                        }
                        for _ in 0..n {
                            let tok = next("an item")?;
                            if *role == Role::Corners {
                                let v = ascii_uint(ctx, no, tok, "vertex index")?;
                                if ascii_scalar(tok, item).is_none() {
                                    return Err(ctx.parse(
                                        at(),
                                        format!(
                                            "vertex index {v} does not fit the index type {item:?}"
                                        ),
                                    ));
                                }
                                let v = u32::try_from(v).map_err(|_| {
                                    ctx.parse(at(), format!("vertex index {v} exceeds 2^32-1"))
                                })?;
                                idx.push(v);
                            } else if ascii_scalar(tok, item).is_none() {
                                return Err(ctx.parse(
                                    at(),
                                    format!(
                                        "{} {k}: invalid item '{tok}' in list '{}'",
                                        e.name, prop.name
                                    ),
                                ));
                            }
                        }
                    }
                }
            }
            if t.next().is_some() {
                return Err(ctx.parse(
                    at(),
                    format!("{} {k}: more values than the declared properties", e.name),
                ));
            }
            match e.kind {
                ElemKind::Vertex => {
                    body.positions.push(p);
                    body.vertex_origin.push(no);
                }
                ElemKind::Face => body.sink.push(ctx, &idx, no, at())?,
                ElemKind::Other => {}
            }
        }
    }
    while let Some((no, line)) = lines.next_line() {
        match line {
            Err(_) => return Err(ctx.encoding(Location::Line(no))),
            Ok(s) if !s.trim().is_empty() => {
                return Err(ctx.parse(
                    Location::Line(no),
                    "unexpected data after the last declared element",
                ))
            }
            Ok(_) => {}
        }
    }
    Ok(())
}

/// An ascii value of type `sc`: integers must be integers in range, floats any float.
fn ascii_scalar(tok: &str, sc: Scalar) -> Option<f64> {
    Some(match sc {
        Scalar::I8 => f64::from(tok.parse::<i8>().ok()?),
        Scalar::U8 => f64::from(tok.parse::<u8>().ok()?),
        Scalar::I16 => f64::from(tok.parse::<i16>().ok()?),
        Scalar::U16 => f64::from(tok.parse::<u16>().ok()?),
        Scalar::I32 => f64::from(tok.parse::<i32>().ok()?),
        Scalar::U32 => f64::from(tok.parse::<u32>().ok()?),
        Scalar::F32 | Scalar::F64 => parse_coord(tok)?,
    })
}

/// A read position in a binary body.
struct Cursor<'a> {
    data: &'a [u8],
    pos: usize,
    be: bool,
}

/// A binary scalar value.
#[derive(Clone, Copy)]
enum Value {
    Int(i64),
    Float(f64),
}

impl Value {
    fn as_f64(self) -> f64 {
        match self {
            Value::Int(i) => i as f64,
            Value::Float(f) => f,
        }
    }
}

impl Cursor<'_> {
    fn remaining(&self) -> usize {
        self.data.len().saturating_sub(self.pos)
    }

    fn take<const N: usize>(&mut self) -> Option<[u8; N]> {
        let end = self.pos.checked_add(N)?;
        let bytes: [u8; N] = self.data.get(self.pos..end)?.try_into().ok()?;
        self.pos = end;
        Some(bytes)
    }

    fn skip(&mut self, n: usize) -> Option<()> {
        let end = self.pos.checked_add(n)?;
        if end > self.data.len() {
            return None;
        }
        self.pos = end;
        Some(())
    }

    fn read(&mut self, sc: Scalar) -> Option<Value> {
        macro_rules! num {
            ($t:ty, $n:literal) => {{
                let b = self.take::<$n>()?;
                if self.be {
                    <$t>::from_be_bytes(b)
                } else {
                    <$t>::from_le_bytes(b)
                }
            }};
        }
        Some(match sc {
            Scalar::I8 => Value::Int(i64::from(num!(i8, 1))),
            Scalar::U8 => Value::Int(i64::from(num!(u8, 1))),
            Scalar::I16 => Value::Int(i64::from(num!(i16, 2))),
            Scalar::U16 => Value::Int(i64::from(num!(u16, 2))),
            Scalar::I32 => Value::Int(i64::from(num!(i32, 4))),
            Scalar::U32 => Value::Int(i64::from(num!(u32, 4))),
            Scalar::F32 => Value::Float(f64::from(num!(f32, 4))),
            Scalar::F64 => Value::Float(num!(f64, 8)),
        })
    }
}

fn read_binary(
    ctx: &Ctx<'_>,
    elements: &[Element],
    cur: &mut Cursor<'_>,
    body_offset: usize,
    body: &mut Body,
) -> Result<(), MeshError> {
    let mut idx: Vec<u32> = Vec::new();
    for e in elements {
        let label = e.kind.label();
        let loc = |k: u64| Location::Element {
            kind: label,
            index: k,
        };
        let truncated = |k: u64| {
            ctx.truncated(
                loc(k),
                format!(
                    "the file ends inside '{}' element {k} of {}",
                    e.name, e.count
                ),
            )
        };
        let fixed: Option<usize> = e
            .props
            .iter()
            .map(|p| match p.kind {
                Kind::Scalar(s) => Some(s.size()),
                Kind::List { .. } => None,
            })
            .sum();
        if let (ElemKind::Other, Some(size)) = (e.kind, fixed) {
            let need = usize::try_from(e.count)
                .ok()
                .and_then(|c| c.checked_mul(size));
            match need {
                Some(n) if n <= cur.remaining() => {
                    cur.pos += n;
                    continue;
                }
                _ => return Err(truncated((cur.remaining() / size.max(1)) as u64)),
            }
        }
        for k in 0..e.count {
            let mut p = [0.0; 3];
            idx.clear();
            for (prop, role) in e.props.iter().zip(&e.roles) {
                match prop.kind {
                    Kind::Scalar(sc) => {
                        let v = cur.read(sc).ok_or_else(|| truncated(k))?;
                        match role {
                            Role::Coord(axis) => {
                                if let Some(c) = p.get_mut(*axis) {
                                    *c = v.as_f64();
                                }
                            }
                            Role::Kept(i) => body.kept[*i].push(v.as_f64()),
                            _ => {}
                        }
                    }
                    Kind::List { count, item } => {
                        let n = match cur.read(count).ok_or_else(|| truncated(k))? {
                            Value::Int(n) if n >= 0 => n as u64,
                            Value::Int(n) => {
                                return Err(ctx.parse(
                                    loc(k),
                                    format!("negative count {n} of list '{}'", prop.name),
                                ))
                            }
                            Value::Float(_) => return Err(truncated(k)),
                        };
                        let bytes = usize::try_from(n)
                            .ok()
                            .and_then(|n| n.checked_mul(item.size()))
                            .filter(|&b| b <= cur.remaining())
                            .ok_or_else(|| truncated(k))?;
                        if *role == Role::Corners {
                            idx.reserve(n as usize);
                            for _ in 0..n {
                                let v = match cur.read(item).ok_or_else(|| truncated(k))? {
                                    Value::Int(v) => v,
                                    Value::Float(_) => return Err(truncated(k)),
                                };
                                let v = u32::try_from(v).map_err(|_| {
                                    ctx.parse(loc(k), format!("negative vertex index {v}"))
                                })?;
                                idx.push(v);
                            }
                        } else {
                            cur.skip(bytes).ok_or_else(|| truncated(k))?;
                        }
                    }
                }
            }
            match e.kind {
                ElemKind::Vertex => {
                    body.positions.push(p);
                    body.vertex_origin.push(k);
                }
                ElemKind::Face => body.sink.push(ctx, &idx, k, loc(k))?,
                ElemKind::Other => {}
            }
        }
    }
    if cur.remaining() > 0 {
        return Err(ctx.parse(
            Location::Byte(cur.pos.saturating_add(body_offset) as u64),
            format!(
                "{} bytes of unexpected data after the last declared element",
                cur.remaining()
            ),
        ));
    }
    Ok(())
}
