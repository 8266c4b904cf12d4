//! The objects of a scene file: geometry (patches built from their nets, meshes described for
//! the engine to make), transform steps and material.

use glam::DVec3;

use super::MAX_BEZIER_DEGREE;
use super::MAX_PROFILE_SEGMENTS;
use super::format::{MaterialSpec, ObjectSpec, ScaleSpec, Step};
use super::textures::c3;
use crate::surface::menger;
use crate::surface::mesh::{self, SurfacePatch, TexMap};
use crate::surface::{
    Geometry, GeometrySpec, Material, Patch, QuaternionJulia, SliceAxis, Transform,
};

fn v3(a: [f64; 3]) -> DVec3 {
    DVec3::from_array(a)
}

/// An object's material: the defaults where the table says nothing.
pub(super) fn material(m: Option<&MaterialSpec>) -> Material {
    let dm = Material::default();
    Material {
        ka: m.and_then(|m| m.ka).unwrap_or(dm.ka),
        kd: m.and_then(|m| m.kd).unwrap_or(dm.kd),
        ks: m.and_then(|m| m.ks).unwrap_or(dm.ks),
        shininess: m.and_then(|m| m.n).unwrap_or(dm.shininess),
        color: m.and_then(|m| m.color).map_or(dm.color, c3),
        two_sided: m.and_then(|m| m.two_sided).unwrap_or(dm.two_sided),
        bump: m.and_then(|m| m.bump).unwrap_or(0.0),
    }
}

/// The transform of an object's steps, applied in order.
pub(super) fn make_transform(steps: &[Step]) -> Result<Transform, String> {
    let mut t = Transform::IDENTITY;
    for s in steps {
        let mut any = 0;
        let mut add = |m: Transform| {
            any += 1;
            t = t.then(&m);
        };
        if let Some(v) = s.scale.as_ref() {
            add(match v {
                ScaleSpec::Uniform(k) => Transform::scale(*k, *k, *k),
                ScaleSpec::Axes(a) => Transform::scale(a[0], a[1], a[2]),
            });
        }
        if let Some(a) = s.shear {
            add(Transform::shear(a[0], a[1], a[2], a[3], a[4], a[5]));
        }
        if let Some(d) = s.rotate_x {
            add(Transform::rot_x(d.to_radians()));
        }
        if let Some(d) = s.rotate_y {
            add(Transform::rot_y(d.to_radians()));
        }
        if let Some(d) = s.rotate_z {
            add(Transform::rot_z(d.to_radians()));
        }
        if let Some(a) = s.rotate_axis {
            let n = DVec3::new(a[0], a[1], a[2]);
            if n.length_squared() == 0.0 {
                return Err("rotate_axis needs a non-zero axis".into());
            }
            let p = s.through.map_or(DVec3::ZERO, v3);
            add(Transform::rot_axis_through(p, n, a[3].to_radians()));
        }
        if let Some(r) = &s.reflect {
            add(match r.as_str() {
                "xy" => Transform::reflect_xy(),
                "yz" => Transform::reflect_yz(),
                "xz" => Transform::reflect_xz(),
                o => return Err(format!("reflect '{o}': expected xy, yz or xz")),
            });
        }
        if let Some(v) = s.translate {
            add(Transform::translate(v[0], v[1], v[2]));
        }
        if any != 1 {
            return Err("each transform step needs exactly one operation".into());
        }
    }
    Ok(t)
}

/// Subdivision levels of a mountain (1..10; the caller warns when clamped).
pub(super) fn mountain_levels(o: &ObjectSpec) -> u32 {
    o.levels.unwrap_or(7).clamp(1, 10)
}

/// Bytes of a mountain's mesh: (2^levels + 1)² vertices, two triangles per cell.
pub(super) fn mountain_bytes(levels: u32) -> u64 {
    let side = (1u64 << levels) + 1;
    side * side * (24 + 24 + 8 + 48 + 8) + 2 * (side - 1) * (side - 1) * 12
}

/// An object's geometry: patches and quaternion Julia sets as given, mountains and Menger
/// sponges as meshes to make.
pub(super) fn geometry_spec(o: &ObjectSpec) -> Result<GeometrySpec, String> {
    Ok(GeometrySpec::Given(match o.kind.as_str() {
        "jug" => Geometry::Patches(mesh::jug()),
        "teapot" => Geometry::Patches(mesh::teapot()),
        "revolve" => {
            let p = o.profile.as_ref().ok_or("needs profile = [[r, y], …]")?;
            if p.len() > 3 * MAX_PROFILE_SEGMENTS + 1 {
                return Err(format!(
                    "profile has {} points: at most {} ({MAX_PROFILE_SEGMENTS} cubic segments)",
                    p.len(),
                    3 * MAX_PROFILE_SEGMENTS + 1
                ));
            }
            if p.len() < 4 || (p.len() - 1) % 3 != 0 {
                return Err(format!(
                    "profile has {} points: needs 3k + 1 (k ≥ 1 cubic segments)",
                    p.len()
                ));
            }
            Geometry::Patches(mesh::revolve(p))
        }
        "tube" => {
            let s = o.spine.as_ref().ok_or("needs spine = 4 points")?;
            let s: [[f64; 3]; 4] = s
                .clone()
                .try_into()
                .map_err(|_| "spine needs exactly 4 points")?;
            let r = o.radius.unwrap_or(0.1);
            if r <= 0.0 {
                return Err("radius must be positive".into());
            }
            Geometry::Patches(mesh::tube(s.map(v3), r))
        }
        "bezier" => {
            let [n, m] = o.degree.unwrap_or([3, 3]);
            if !(1..=MAX_BEZIER_DEGREE).contains(&n) || !(1..=MAX_BEZIER_DEGREE).contains(&m) {
                return Err(format!(
                    "degree [{n}, {m}]: each must be between 1 and {MAX_BEZIER_DEGREE}"
                ));
            }
            let net = o.net.as_ref().ok_or("needs net = [[x, y, z], …]")?;
            let p = Patch::bezier(n, m, net.iter().map(|p| v3(*p)).collect())
                .map_err(|e| e.to_string())?;
            Geometry::Patches(vec![SurfacePatch {
                patch: p,
                tex: TexMap::default(),
            }])
        }
        "bilinear" => {
            let c = o.corners.as_ref().ok_or("needs corners = 4 points")?;
            let c: [[f64; 3]; 4] = c
                .clone()
                .try_into()
                .map_err(|_| "corners needs exactly 4 points")?;
            Geometry::Patches(vec![SurfacePatch {
                patch: Patch::Bilinear { p: c.map(v3) },
                tex: TexMap::default(),
            }])
        }
        "mountain" => {
            return Ok(GeometrySpec::Mountain {
                levels: mountain_levels(o),
                size: o.size.unwrap_or(6.0),
                sigma: o.sigma.unwrap_or(1.0),
                h: o.h.unwrap_or(0.8),
                seed: o.seed.unwrap_or(1),
            });
        }
        "menger" => {
            let step = o.step.unwrap_or(3);
            if step > menger::MAX_STEP {
                return Err(format!(
                    "step {step} is too deep: expected 0 to {} (step {} has {} cubes)",
                    menger::MAX_STEP,
                    menger::MAX_STEP,
                    menger::numbers(menger::MAX_STEP).cubes
                ));
            }
            let size = o.size.unwrap_or(2.0);
            if !(size > 0.0 && size <= 1e6) {
                return Err(format!("size {size} must be between 0 and 1e6"));
            }
            return Ok(GeometrySpec::Menger { step, size });
        }
        "quaternion_julia" | "qjulia" => {
            let d = QuaternionJulia::default();
            let c = match o.c.as_deref() {
                None => d.c,
                Some([re, im]) => [*re, *im, 0.0, 0.0],
                Some([a, b, c, e]) => [*a, *b, *c, *e],
                Some(v) => {
                    return Err(format!(
                        "c has {} numbers: expected [c0, c1, c2, c3] (or [re, im])",
                        v.len()
                    ));
                }
            };
            let slice = match o.slice.as_deref() {
                None => d.slice,
                Some(n) => SliceAxis::from_name(n).ok_or_else(|| {
                    format!(
                        "slice '{n}': expected the fixed component \"1\", \"i\", \"j\" or \"k\""
                    )
                })?,
            };
            let j = QuaternionJulia {
                c,
                slice,
                slice_value: o.slice_value.unwrap_or(d.slice_value),
                iterations: o.iterations.unwrap_or(d.iterations),
            };
            j.validate()?;
            Geometry::QuaternionJulia(j)
        }
        other => {
            return Err(format!(
                "unknown object kind '{other}': expected jug, teapot, revolve, tube, bezier, bilinear, mountain, menger or quaternion_julia"
            ));
        }
    }))
}
