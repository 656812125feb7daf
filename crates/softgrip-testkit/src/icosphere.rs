//! A closed, outward-oriented sphere surface mesh (subdivided icosahedron): the input of
//! rapier's tetrahedral fill `SoftBodyBuilder::volumetric` in `softgrip-bench`'s FEM table,
//! and the tessellated sphere whose curvature `softgrip-rapier`'s `tests/counterparts.rs`
//! reads.

use std::collections::HashMap;

use rapier3d::prelude::Vector;

/// Vertices and outward triangles of an icosphere of `radius` \[m\] about `center`, with
/// `subdivisions` levels of 4-to-1 refinement (20 * 4^subdivisions triangles).
pub fn icosphere(center: Vector, radius: f32, subdivisions: u32) -> (Vec<Vector>, Vec<[u32; 3]>) {
    let t = (1.0 + 5.0f32.sqrt()) / 2.0;
    let mut vertices: Vec<Vector> = [
        (-1.0, t, 0.0),
        (1.0, t, 0.0),
        (-1.0, -t, 0.0),
        (1.0, -t, 0.0),
        (0.0, -1.0, t),
        (0.0, 1.0, t),
        (0.0, -1.0, -t),
        (0.0, 1.0, -t),
        (t, 0.0, -1.0),
        (t, 0.0, 1.0),
        (-t, 0.0, -1.0),
        (-t, 0.0, 1.0),
    ]
    .iter()
    .map(|&(x, y, z)| Vector::new(x, y, z).normalize())
    .collect();
    let mut triangles: Vec<[u32; 3]> = vec![
        [0, 11, 5],
        [0, 5, 1],
        [0, 1, 7],
        [0, 7, 10],
        [0, 10, 11],
        [1, 5, 9],
        [5, 11, 4],
        [11, 10, 2],
        [10, 7, 6],
        [7, 1, 8],
        [3, 9, 4],
        [3, 4, 2],
        [3, 2, 6],
        [3, 6, 8],
        [3, 8, 9],
        [4, 9, 5],
        [2, 4, 11],
        [6, 2, 10],
        [8, 6, 7],
        [9, 8, 1],
    ];
    for _ in 0..subdivisions {
        let mut midpoints: HashMap<(u32, u32), u32> = HashMap::new();
        let mut midpoint = |a: u32, b: u32, vertices: &mut Vec<Vector>| -> u32 {
            *midpoints.entry((a.min(b), a.max(b))).or_insert_with(|| {
                let m = (vertices[a as usize] + vertices[b as usize]).normalize();
                vertices.push(m);
                (vertices.len() - 1) as u32
            })
        };
        let mut refined = Vec::with_capacity(triangles.len() * 4);
        for [a, b, c] in triangles {
            let ab = midpoint(a, b, &mut vertices);
            let bc = midpoint(b, c, &mut vertices);
            let ca = midpoint(c, a, &mut vertices);
            refined.extend([[a, ab, ca], [b, bc, ab], [c, ca, bc], [ab, bc, ca]]);
        }
        triangles = refined;
    }
    let vertices = vertices.iter().map(|v| center + *v * radius).collect();
    (vertices, triangles)
}
