//! 4×4 homogeneous transforms in Köse's (1990) row-vector convention:
//! [X Y Z H] = [x y z 1]·T; "first T₁, then T₂" is T₁·T₂.

use glam::{DVec3, DVec4};

/// A 4×4 matrix, rows as in Köse's (1990) tables.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Transform(pub [[f64; 4]; 4]);

impl Default for Transform {
    fn default() -> Self {
        Transform::IDENTITY
    }
}

impl Transform {
    /// The transform that changes nothing.
    pub const IDENTITY: Transform = Transform([
        [1.0, 0.0, 0.0, 0.0],
        [0.0, 1.0, 0.0, 0.0],
        [0.0, 0.0, 1.0, 0.0],
        [0.0, 0.0, 0.0, 1.0],
    ]);

    /// [x y z 1]·T as homogeneous [X Y Z H].
    pub fn apply_h(&self, p: DVec3) -> DVec4 {
        let m = &self.0;
        let v = [p.x, p.y, p.z, 1.0];
        let mut o = [0.0; 4];
        for (c, oc) in o.iter_mut().enumerate() {
            *oc = v[0] * m[0][c] + v[1] * m[1][c] + v[2] * m[2][c] + v[3] * m[3][c];
        }
        DVec4::new(o[0], o[1], o[2], o[3])
    }

    /// The transformed point after the homogeneous divide.
    pub fn apply(&self, p: DVec3) -> DVec3 {
        let h = self.apply_h(p);
        DVec3::new(h.x / h.w, h.y / h.w, h.z / h.w)
    }

    /// A direction (w = 0): only the linear block.
    pub fn apply_dir(&self, d: DVec3) -> DVec3 {
        let m = &self.0;
        DVec3::new(
            d.x * m[0][0] + d.y * m[1][0] + d.z * m[2][0],
            d.x * m[0][1] + d.y * m[1][1] + d.z * m[2][1],
            d.x * m[0][2] + d.y * m[1][2] + d.z * m[2][2],
        )
    }

    /// The inverse matrix (None when singular), e.g. to map rays back into object space.
    pub fn inverse(&self) -> Option<Transform> {
        // In glam's column-vector convention this matrix is Tᵀ; (Tᵀ)⁻¹ = (T⁻¹)ᵀ.
        let m = glam::DMat4::from_cols_array_2d(&self.0);
        let det = m.determinant();
        if det == 0.0 || !det.is_finite() {
            return None;
        }
        Some(Transform(m.inverse().to_cols_array_2d()))
    }

    /// Is this an affine map (last column [0 0 0 1]ᵀ)?
    pub fn is_affine(&self) -> bool {
        let m = &self.0;
        m[0][3] == 0.0 && m[1][3] == 0.0 && m[2][3] == 0.0 && m[3][3] == 1.0
    }

    /// A normal vector through the linear block: the inverse transpose, n′ = n·(L⁻¹)ᵀ in
    /// the row-vector convention, so that n′ stays perpendicular to transformed tangents.
    pub fn apply_normal(&self, n: DVec3) -> DVec3 {
        let m = &self.0;
        // Column-vector form M = Lᵀ; normals go through (M⁻¹)ᵀ = cofactor(M)/det.
        let l = glam::DMat3::from_cols_array_2d(&[
            [m[0][0], m[0][1], m[0][2]],
            [m[1][0], m[1][1], m[1][2]],
            [m[2][0], m[2][1], m[2][2]],
        ]);
        let det = l.determinant();
        if det == 0.0 {
            return n;
        }
        // Keep the orientation of Q_u × Q_w under the map (L Q_u) × (L Q_w) = det·(L⁻ᵀ)(Q_u × Q_w).
        (l.inverse().transpose() * n) * det.signum()
    }

    /// First self, then `next` (self·next).
    pub fn then(&self, next: &Transform) -> Transform {
        let (a, b) = (&self.0, &next.0);
        let mut o = [[0.0; 4]; 4];
        for (r, row) in o.iter_mut().enumerate() {
            for (c, v) in row.iter_mut().enumerate() {
                *v = (0..4).map(|k| a[r][k] * b[k][c]).sum();
            }
        }
        Transform(o)
    }

    /// Local scaling diag(a, e, j, 1).
    pub fn scale(sx: f64, sy: f64, sz: f64) -> Transform {
        Transform([
            [sx, 0.0, 0.0, 0.0],
            [0.0, sy, 0.0, 0.0],
            [0.0, 0.0, sz, 0.0],
            [0.0, 0.0, 0.0, 1.0],
        ])
    }

    /// Overall scaling diag(1, 1, 1, s): s > 1 shrinks.
    pub fn overall_scale(s: f64) -> Transform {
        let mut t = Transform::IDENTITY;
        t.0[3][3] = s;
        t
    }

    /// Shear: (x + dy + hz, bx + y + iz, cx + fy + z).
    pub fn shear(b: f64, c: f64, d: f64, f: f64, h: f64, i: f64) -> Transform {
        Transform([
            [1.0, b, c, 0.0],
            [d, 1.0, f, 0.0],
            [h, i, 1.0, 0.0],
            [0.0, 0.0, 0.0, 1.0],
        ])
    }

    /// Reflection in the xy plane (z → −z).
    pub fn reflect_xy() -> Transform {
        Transform::scale(1.0, 1.0, -1.0)
    }

    /// Reflection in the yz plane (x → −x).
    pub fn reflect_yz() -> Transform {
        Transform::scale(-1.0, 1.0, 1.0)
    }

    /// Reflection in the xz plane (y → −y).
    pub fn reflect_xz() -> Transform {
        Transform::scale(1.0, -1.0, 1.0)
    }

    /// Translation by (l, m, n).
    pub fn translate(l: f64, m: f64, n: f64) -> Transform {
        let mut t = Transform::IDENTITY;
        t.0[3] = [l, m, n, 1.0];
        t
    }

    /// Rotation about x by θ radians (counter-clockwise looking from +x to the origin).
    pub fn rot_x(th: f64) -> Transform {
        let (s, c) = th.sin_cos();
        Transform([
            [1.0, 0.0, 0.0, 0.0],
            [0.0, c, s, 0.0],
            [0.0, -s, c, 0.0],
            [0.0, 0.0, 0.0, 1.0],
        ])
    }

    /// Rotation about y by θ radians.
    pub fn rot_y(th: f64) -> Transform {
        let (s, c) = th.sin_cos();
        Transform([
            [c, 0.0, -s, 0.0],
            [0.0, 1.0, 0.0, 0.0],
            [s, 0.0, c, 0.0],
            [0.0, 0.0, 0.0, 1.0],
        ])
    }

    /// Rotation about z by θ radians.
    pub fn rot_z(th: f64) -> Transform {
        let (s, c) = th.sin_cos();
        Transform([
            [c, s, 0.0, 0.0],
            [-s, c, 0.0, 0.0],
            [0.0, 0.0, 1.0, 0.0],
            [0.0, 0.0, 0.0, 1.0],
        ])
    }

    /// Rotation by θ about the axis n through the origin (Köse 1990, eq. 3.11; n is normalised).
    pub fn rot_axis(n: DVec3, th: f64) -> Transform {
        let n = n.normalize();
        let (s, c) = th.sin_cos();
        let (n1, n2, n3) = (n.x, n.y, n.z);
        let k = 1.0 - c;
        Transform([
            [
                n1 * n1 + (1.0 - n1 * n1) * c,
                n1 * n2 * k + n3 * s,
                n1 * n3 * k - n2 * s,
                0.0,
            ],
            [
                n1 * n2 * k - n3 * s,
                n2 * n2 + (1.0 - n2 * n2) * c,
                n2 * n3 * k + n1 * s,
                0.0,
            ],
            [
                n1 * n3 * k + n2 * s,
                n2 * n3 * k - n1 * s,
                n3 * n3 + (1.0 - n3 * n3) * c,
                0.0,
            ],
            [0.0, 0.0, 0.0, 1.0],
        ])
    }

    /// Rotation about an axis through point p: translate by −p, rotate, translate back.
    pub fn rot_axis_through(p: DVec3, n: DVec3, th: f64) -> Transform {
        Transform::translate(-p.x, -p.y, -p.z)
            .then(&Transform::rot_axis(n, th))
            .then(&Transform::translate(p.x, p.y, p.z))
    }

    /// Single-point perspective onto z = 0 (Köse 1990, eq. 3.16): x* = x/(rz + 1).
    pub fn perspective(r: f64) -> Transform {
        Transform([
            [1.0, 0.0, 0.0, 0.0],
            [0.0, 1.0, 0.0, 0.0],
            [0.0, 0.0, 0.0, r],
            [0.0, 0.0, 0.0, 1.0],
        ])
    }

    /// Perspective with the centre of projection at z = k that keeps depth:
    /// z* = z/(1 − z/k), monotonic for z < k.
    pub fn perspective_depth(k: f64) -> Transform {
        Transform([
            [1.0, 0.0, 0.0, 0.0],
            [0.0, 1.0, 0.0, 0.0],
            [0.0, 0.0, 1.0, -1.0 / k],
            [0.0, 0.0, 0.0, 1.0],
        ])
    }

    /// Orthographic projection onto z = n (Köse 1990, eq. 3.17).
    pub fn orthographic(n: f64) -> Transform {
        Transform([
            [1.0, 0.0, 0.0, 0.0],
            [0.0, 1.0, 0.0, 0.0],
            [0.0, 0.0, 0.0, 0.0],
            [0.0, 0.0, n, 1.0],
        ])
    }

    /// Axonometric: rotate about y by φ, then about x by θ (projection onto z = 0 is then
    /// dropping z; depth is kept here for hidden-surface removal).
    pub fn axonometric(phi: f64, theta: f64) -> Transform {
        Transform::rot_y(phi).then(&Transform::rot_x(theta))
    }

    /// Stereo pair (Köse 1990, corrected): `left` is matrix A (eye at x = −k/20).
    pub fn stereo(k: f64, left: bool) -> Transform {
        let dx = if left { k / 20.0 } else { -k / 20.0 };
        Transform([
            [1.0, 0.0, 0.0, 0.0],
            [0.0, 1.0, 0.0, 0.0],
            [0.0, 0.0, 0.0, -1.0 / k],
            [dx, 0.0, 0.0, 1.0],
        ])
    }
}

/// Isometric angles (φ, θ) = (45°, 35.2644°).
pub fn isometric_angles() -> (f64, f64) {
    (std::f64::consts::FRAC_PI_4, (1.0f64 / 3.0).sqrt().asin())
}

/// Dimetric angles for f_x = f_y and a chosen f_z: θ = asin(f_z/√2), φ = asin(f_z/√(2 − f_z²)).
pub fn dimetric_angles(fz: f64) -> (f64, f64) {
    let theta = (fz / 2f64.sqrt()).asin();
    let phi = (fz / (2.0 - fz * fz).sqrt()).asin();
    (phi, theta)
}

/// Foreshortening factors (f_x, f_y, f_z) of an axonometric projection.
#[cfg(test)]
pub fn foreshortening(phi: f64, theta: f64) -> (f64, f64, f64) {
    let t = Transform::axonometric(phi, theta);
    let f = |d: DVec3| {
        let v = t.apply_dir(d);
        (v.x * v.x + v.y * v.y).sqrt()
    };
    (f(DVec3::X), f(DVec3::Y), f(DVec3::Z))
}

/// Newell's polygon normal (a, b, c) and d.
#[cfg(test)]
pub fn newell(points: &[DVec3]) -> (DVec3, f64) {
    let mut n = DVec3::ZERO;
    for i in 0..points.len() {
        let (p, q) = (points[i], points[(i + 1) % points.len()]);
        n.x += (p.y - q.y) * (p.z + q.z);
        n.y += (p.z - q.z) * (p.x + q.x);
        n.z += (p.x - q.x) * (p.y + q.y);
    }
    let d = points.first().map_or(0.0, |p| -n.dot(*p));
    (n, d)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn close(a: DVec3, b: DVec3) -> bool {
        (a - b).length() < 1e-12
    }

    #[test]
    fn rotation_and_projection_oracles() {
        let q = std::f64::consts::FRAC_PI_2;
        assert!(close(Transform::rot_z(q).apply(DVec3::X), DVec3::Y));
        assert!(close(Transform::rot_x(q).apply(DVec3::Y), DVec3::Z));
        assert!(close(Transform::rot_y(q).apply(DVec3::Z), DVec3::X));
        let n = DVec3::ONE;
        let r = Transform::rot_axis(n, 120f64.to_radians());
        assert!(close(r.apply(DVec3::X), DVec3::Y));
        assert!(close(r.apply(DVec3::Y), DVec3::Z));
        let rz = Transform::rot_axis(DVec3::Z, 0.7);
        for (a, b) in
            rz.0.iter()
                .flatten()
                .zip(Transform::rot_z(0.7).0.iter().flatten())
        {
            assert!((a - b).abs() < 1e-15);
        }
        // About an axis through a point: the point stays.
        let p = DVec3::new(1.0, 2.0, 3.0);
        assert!(close(
            Transform::rot_axis_through(p, DVec3::Y, 1.1).apply(p),
            p
        ));
        // Perspective r = 0.1 on (2, 4, 10): H = 2, (x*, y*) = (1, 2).
        let h = Transform::perspective(0.1).apply_h(DVec3::new(2.0, 4.0, 10.0));
        assert!(
            (h.w - 2.0).abs() < 1e-15
                && (h.x / h.w - 1.0).abs() < 1e-15
                && (h.y / h.w - 2.0).abs() < 1e-15
        );
        // Depth-keeping perspective is monotonic in z for z < k.
        let t = Transform::perspective_depth(10.0);
        let zs: Vec<f64> = [-5.0, 0.0, 3.0, 9.0]
            .iter()
            .map(|z| t.apply(DVec3::new(0.0, 0.0, *z)).z)
            .collect();
        assert!(zs.windows(2).all(|w| w[0] < w[1]));
        // Orthographic onto z = n.
        assert!(close(
            Transform::orthographic(2.0).apply(DVec3::new(1.0, 2.0, 7.0)),
            DVec3::new(1.0, 2.0, 2.0)
        ));
        // Stereo k = 50: origin → ±2.5; z = −50 → ±1.25.
        let a = Transform::stereo(50.0, true);
        let b = Transform::stereo(50.0, false);
        assert!((a.apply(DVec3::ZERO).x - 2.5).abs() < 1e-12);
        assert!((b.apply(DVec3::ZERO).x + 2.5).abs() < 1e-12);
        assert!((a.apply(DVec3::new(0.0, 0.0, -50.0)).x - 1.25).abs() < 1e-12);
        assert!((b.apply(DVec3::new(0.0, 0.0, -50.0)).x + 1.25).abs() < 1e-12);
    }

    #[test]
    fn basic_transforms_and_composition() {
        let p = DVec3::new(1.0, 2.0, 3.0);
        assert!(close(
            Transform::translate(1.0, -1.0, 2.0).apply(p),
            DVec3::new(2.0, 1.0, 5.0)
        ));
        assert!(close(Transform::overall_scale(2.0).apply(p), p / 2.0));
        assert!(close(
            Transform::reflect_yz().apply(p),
            DVec3::new(-1.0, 2.0, 3.0)
        ));
        assert!(close(
            Transform::reflect_xz().apply(p),
            DVec3::new(1.0, -2.0, 3.0)
        ));
        assert!(close(
            Transform::reflect_xy().apply(p),
            DVec3::new(1.0, 2.0, -3.0)
        ));
        let sh = Transform::shear(0.1, 0.2, 0.3, 0.4, 0.5, 0.6).apply(p);
        assert!(close(
            sh,
            DVec3::new(1.0 + 0.6 + 1.5, 0.1 + 2.0 + 1.8, 0.2 + 0.8 + 3.0)
        ));
        // First translate, then rotate: T₁·T₂.
        let t = Transform::translate(1.0, 0.0, 0.0)
            .then(&Transform::rot_z(std::f64::consts::FRAC_PI_2));
        assert!(close(t.apply(DVec3::ZERO), DVec3::Y));
    }

    #[test]
    fn axonometric_oracles_and_newell() {
        let (phi, theta) = isometric_angles();
        assert!((theta.to_degrees() - 35.2644).abs() < 1e-4);
        let (fx, fy, fz) = foreshortening(phi, theta);
        for f in [fx, fy, fz] {
            assert!((f - 0.816497).abs() < 1e-6, "{f}");
        }
        let (phi, theta) = dimetric_angles(0.5);
        assert!((theta.to_degrees() - 20.7048).abs() < 1e-4);
        assert!((phi.to_degrees() - 22.2077).abs() < 1e-4);
        let (fx, fy, fz) = foreshortening(phi, theta);
        assert!(
            (fx - 0.935414).abs() < 1e-6 && (fy - 0.935414).abs() < 1e-6 && (fz - 0.5).abs() < 1e-9
        );
        let sq = [DVec3::ZERO, DVec3::X, DVec3::new(1.0, 1.0, 0.0), DVec3::Y];
        assert!(close(newell(&sq).0, DVec3::new(0.0, 0.0, 2.0)));
        let (n, d) = newell(&[DVec3::X, DVec3::Y, DVec3::Z]);
        assert!(close(n, DVec3::ONE) && (d + 1.0).abs() < 1e-15);
    }
}
