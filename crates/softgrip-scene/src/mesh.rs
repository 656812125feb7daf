//! Small mesh readers: Wavefront OBJ (`v` and `f` lines) and STL (binary and ASCII).

use std::collections::HashMap;
use std::path::Path;

use crate::error::SceneError;
use crate::limits::{MAX_COORDINATE, MAX_MESH_BYTES};
use crate::read::{ReadError, read_regular, strip_bom, strip_bom_str};

/// A triangle mesh: vertices \[m\] and counter-clockwise triangles (indices into `vertices`).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Mesh {
    /// Vertex positions.
    pub vertices: Vec<[f64; 3]>,
    /// Triangles as vertex indices.
    pub triangles: Vec<[u32; 3]>,
}

/// Reads an `.obj` or `.stl` file (chosen by extension, case-insensitive).
pub fn load_mesh(path: &Path) -> Result<Mesh, SceneError> {
    let err = |line, message: String| SceneError::Mesh {
        path: path.to_path_buf(),
        line,
        message,
    };
    let bytes = read_regular(path, MAX_MESH_BYTES).map_err(|e| match e {
        ReadError::TooLarge { limit } => SceneError::TooLarge {
            path: path.to_path_buf(),
            what: "mesh",
            limit,
        },
        e => err(0, e.message()),
    })?;
    let ext = path
        .extension()
        .and_then(|e| e.to_str())
        .map(str::to_ascii_lowercase);
    let mesh = match ext.as_deref() {
        Some("obj") => parse_obj(&String::from_utf8_lossy(&bytes)),
        Some("stl") => parse_stl(&bytes),
        _ => Err((
            0,
            String::from("unknown mesh format: expected .obj or .stl"),
        )),
    }
    .map_err(|(line, m)| err(line, m))?;
    if mesh.triangles.is_empty() {
        return Err(err(0, String::from("the mesh has no triangles")));
    }
    Ok(mesh)
}

/// Parses OBJ text: `v x y z` and `f i j k ...` (1-based or negative indices, `i/t/n` forms;
/// polygons are fanned into triangles). Other lines are ignored. Errors carry the line. A
/// leading byte-order mark is not part of the first line (it hid the first vertex).
pub fn parse_obj(text: &str) -> Result<Mesh, (usize, String)> {
    let mut mesh = Mesh::default();
    for (i, line) in strip_bom_str(text).lines().enumerate() {
        let n = i + 1;
        let mut words = line.split_whitespace();
        match words.next() {
            Some("v") => {
                let mut p = [0.0; 3];
                for c in &mut p {
                    let w = words
                        .next()
                        .ok_or((n, String::from("`v` needs 3 numbers")))?;
                    *c = w
                        .parse()
                        .map_err(|_| (n, format!("`{w}` is not a number")))?;
                }
                mesh.vertices.push(p);
            }
            Some("f") => {
                let mut idx = Vec::new();
                for w in words {
                    let first = w.split('/').next().unwrap_or(w);
                    let k: i64 = first
                        .parse()
                        .map_err(|_| (n, format!("`{w}` is not a vertex index")))?;
                    let count = mesh.vertices.len() as i64;
                    let k = if k < 0 { count + k } else { k - 1 };
                    if !(0..count).contains(&k) {
                        return Err((n, format!("vertex index `{w}` is out of range")));
                    }
                    idx.push(k as u32);
                }
                if idx.len() < 3 {
                    return Err((n, String::from("a face needs at least 3 vertices")));
                }
                for j in 1..idx.len() - 1 {
                    mesh.triangles.push([idx[0], idx[j], idx[j + 1]]);
                }
            }
            _ => {}
        }
    }
    Ok(mesh)
}

/// Parses STL, binary (80-byte header, count, 50-byte records) or ASCII (`vertex` lines).
/// Equal vertices are merged. An ASCII file may start with a byte-order mark.
pub fn parse_stl(bytes: &[u8]) -> Result<Mesh, (usize, String)> {
    let binary_len = |b: &[u8]| {
        b.get(80..84)
            .map(|c| 84 + 50 * u32::from_le_bytes([c[0], c[1], c[2], c[3]]) as usize)
    };
    let mut corners: Vec<[f64; 3]> = Vec::new();
    if binary_len(bytes) == Some(bytes.len()) {
        for rec in bytes[84..].chunks_exact(50) {
            for v in 0..3 {
                let mut p = [0.0; 3];
                for (c, x) in p.iter_mut().enumerate() {
                    let o = 12 + 12 * v + 4 * c;
                    *x = f32::from_le_bytes([rec[o], rec[o + 1], rec[o + 2], rec[o + 3]]) as f64;
                }
                corners.push(p);
            }
        }
    } else {
        let text = std::str::from_utf8(strip_bom(bytes))
            .map_err(|_| (0, String::from("neither binary STL nor ASCII text")))?;
        if !text.trim_start().starts_with("solid") {
            return Err((1, String::from("ASCII STL must start with `solid`")));
        }
        for (i, line) in text.lines().enumerate() {
            let mut words = line.split_whitespace();
            if words.next() != Some("vertex") {
                continue;
            }
            let mut p = [0.0; 3];
            for c in &mut p {
                let w = words
                    .next()
                    .ok_or((i + 1, String::from("`vertex` needs 3 numbers")))?;
                *c = w
                    .parse()
                    .map_err(|_| (i + 1, format!("`{w}` is not a number")))?;
            }
            corners.push(p);
        }
        if !corners.len().is_multiple_of(3) {
            return Err((0, String::from("the vertex count is not a multiple of 3")));
        }
    }
    let mut mesh = Mesh::default();
    let mut index: HashMap<[u64; 3], u32> = HashMap::new();
    let mut tri = [0u32; 3];
    for (k, p) in corners.iter().enumerate() {
        let key = p.map(f64::to_bits);
        let id = *index.entry(key).or_insert_with(|| {
            mesh.vertices.push(*p);
            (mesh.vertices.len() - 1) as u32
        });
        tri[k % 3] = id;
        if k % 3 == 2 {
            mesh.triangles.push(tri);
        }
    }
    Ok(mesh)
}

/// What rapier can hold of a (scaled) mesh, as rapier will hold it (vertices rounded to
/// `f32`): every vertex finite and within [`MAX_COORDINATE`]; for a triangle mesh no
/// degenerate triangle (twice its area > `f32::EPSILON` times its longest edge squared); for a
/// convex mesh a hull that spans a volume (not all points coplanar). The error names the
/// vertex or triangle (0-based, in file order).
pub(crate) fn check_geometry(mesh: &Mesh, convex: bool) -> Result<(), String> {
    for (k, v) in mesh.vertices.iter().enumerate() {
        if !v.iter().all(|c| c.is_finite() && c.abs() <= MAX_COORDINATE) {
            return Err(format!(
                "vertex {k} is {v:?}: each coordinate must be finite and within ±{MAX_COORDINATE:e} m (after `scale`)"
            ));
        }
    }
    let p: Vec<[f64; 3]> = (mesh.vertices.iter())
        .map(|v| v.map(|c| c as f32 as f64))
        .collect();
    if convex {
        return spans_volume(&p)
            .then_some(())
            .ok_or_else(|| String::from("the convex hull is flat (all vertices coplanar or collinear): a `convex_mesh` needs a non-degenerate hull"));
    }
    for (k, t) in mesh.triangles.iter().enumerate() {
        let [a, b, c] = t.map(|i| p[i as usize]);
        let (e1, e2, e3) = (sub(b, a), sub(c, a), sub(c, b));
        let longest = [e1, e2, e3].iter().map(|e| dot(*e, *e)).fold(0.0, f64::max);
        let n = cross(e1, e2);
        let twice_area = dot(n, n).sqrt();
        if twice_area.is_nan() || twice_area <= f32::EPSILON as f64 * longest {
            return Err(format!(
                "triangle {k} (vertices {t:?}) is degenerate (zero area): a `triangle_mesh` needs triangles with three distinct, non-collinear corners"
            ));
        }
    }
    Ok(())
}

/// The points span a volume: the tetrahedron of the farthest points (from the first, from
/// their line, from their plane) has a volume > 1e-9 times the cube of the extent.
fn spans_volume(p: &[[f64; 3]]) -> bool {
    let Some(&a) = p.first() else {
        return false;
    };
    let far = |score: &dyn Fn([f64; 3]) -> f64| {
        p.iter()
            .copied()
            .max_by(|x, y| score(*x).total_cmp(&score(*y)))
            .unwrap_or(a)
    };
    let b = far(&|x| dot(sub(x, a), sub(x, a)));
    let ab = sub(b, a);
    let c = far(&|x| {
        let n = cross(ab, sub(x, a));
        dot(n, n)
    });
    let n = cross(ab, sub(c, a));
    let d = far(&|x| dot(n, sub(x, a)).abs());
    let extent = dot(ab, ab).sqrt();
    let volume = dot(n, sub(d, a)).abs() / 6.0;
    volume > 1e-9 * extent * extent * extent
}

fn sub(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}
fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}
fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn obj_quad_is_two_triangles() {
        let m = parse_obj("# quad\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1/1 2/2 3/3 -1\n")
            .expect("valid OBJ");
        assert_eq!(m.vertices.len(), 4);
        assert_eq!(m.triangles, vec![[0, 1, 2], [0, 2, 3]]);
        assert_eq!(parse_obj("v 0 0 0\nf 1 2 3\n").err().map(|e| e.0), Some(2));
    }

    #[test]
    fn stl_ascii_and_binary_agree() {
        let ascii = "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\n\
                     vertex 0 1 0\nendloop\nendfacet\nfacet normal 0 0 1\nouter loop\n\
                     vertex 1 0 0\nvertex 1 1 0\nvertex 0 1 0\nendloop\nendfacet\nendsolid t\n";
        let a = parse_stl(ascii.as_bytes()).expect("valid ASCII STL");
        let mut bin = vec![0u8; 80];
        bin.extend_from_slice(&2u32.to_le_bytes());
        for tri in [
            [[0., 0., 0.], [1., 0., 0.], [0., 1., 0.]],
            [[1., 0., 0.], [1., 1., 0.], [0., 1., 0.]],
        ] {
            bin.extend_from_slice(&[0u8; 12]);
            for v in tri {
                for c in v {
                    bin.extend_from_slice(&(c as f32).to_le_bytes());
                }
            }
            bin.extend_from_slice(&[0u8; 2]);
        }
        let b = parse_stl(&bin).expect("valid binary STL");
        assert_eq!(a, b);
        assert_eq!(a.vertices.len(), 4);
        assert_eq!(a.triangles, vec![[0, 1, 2], [1, 3, 2]]);
    }
}
