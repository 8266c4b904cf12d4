//! Shading shared by both renderers: a visible surface point, its texture and Blinn bump mapping,
//! and the lighting model.

use glam::{DVec3, Vec3};

use super::scene::{Scene, illuminate_visible};

/// Blinn's perturbed normal n′ = N + [P_s (N × Q_t) + P_t (Q_s × N)]/|N| with N = Q_s × Q_t.
#[inline]
pub fn bump_normal(qs: DVec3, qt: DVec3, ps: f64, pt: f64) -> DVec3 {
    let n = qs.cross(qt);
    let len = n.length();
    if len == 0.0 {
        return n;
    }
    n + (n.cross(qt) * ps + qs.cross(n) * pt) / len
}

/// A visible surface point, ready for shading (both renderers).
pub(crate) struct SurfacePoint {
    pub(crate) object: usize,
    pub(crate) pos: DVec3,
    pub(crate) normal: DVec3,
    pub(crate) st: [f64; 2],
    /// Largest change of (s, t) per pixel (mipmap level).
    pub(crate) footprint: f32,
    /// Texture tangents ∂P/∂s and ∂P/∂t (zero: no bump mapping).
    pub(crate) ts: DVec3,
    pub(crate) tt: DVec3,
}

/// Texture, Blinn bump mapping and the lighting model at one surface point; `visible(j)`
/// says whether light j reaches it (shadows).
pub(crate) fn shade(
    scene: &Scene,
    eye_pos: DVec3,
    p: &SurfacePoint,
    visible: &dyn Fn(usize) -> bool,
) -> Vec3 {
    let obj = &scene.objects[p.object];
    let st = p.st;
    let mut normal = p.normal;
    let tex = obj
        .texture
        .and_then(|i| scene.textures.get(i))
        .map_or(Vec3::ONE, |tx| {
            tx.sample(st[0] as f32, st[1] as f32, p.footprint)
        });
    if obj.material.bump != 0.0
        && let Some(bt) = obj
            .bump_texture
            .or(obj.texture)
            .and_then(|i| scene.textures.get(i))
    {
        let (ds, dt) = bt.texel_step();
        let (s0, t0) = (st[0] as f32, st[1] as f32);
        let ps = (bt.height(s0 + ds, t0) - bt.height(s0 - ds, t0)) as f64 / (2.0 * ds as f64);
        let pt = (bt.height(s0, t0 + dt) - bt.height(s0, t0 - dt)) as f64 / (2.0 * dt as f64);
        let (qs, qt) = (p.ts, p.tt);
        let mut nb = bump_normal(qs, qt, ps * obj.material.bump, pt * obj.material.bump);
        let n0 = qs.cross(qt);
        if n0.dot(normal) < 0.0 {
            // The tangent frame is left-handed relative to the shading normal.
            nb = -bump_normal(qt, qs, pt * obj.material.bump, ps * obj.material.bump);
        }
        if nb.length_squared() > 0.0 {
            normal = nb;
        }
    }
    illuminate_visible(
        &obj.material,
        tex,
        normal,
        p.pos,
        eye_pos,
        &scene.lights,
        scene.ambient,
        scene.attenuation_k,
        scene.blinn,
        visible,
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bump_oracle() {
        // Q = (u, w, 0), P = 0.1u → n′ = (−0.1, 0, 1).
        let n = bump_normal(DVec3::X, DVec3::Y, 0.1, 0.0);
        assert!((n - DVec3::new(-0.1, 0.0, 1.0)).length() < 1e-15);
    }
}
