//! JWildfire's affine maps in the yz and zx planes: besides the usual map of the xy plane
//! (`coefs`, `post`) a JWildfire xform may carry maps of the yz and zx planes, before the
//! variations (`yzCoefs`, `zxCoefs`) and after them (`yzPostCoefs`, `zxPostCoefs`), six
//! numbers each in the order of `coefs`. ugnis keeps these attributes as the xform's unread
//! ones ([`Xform::extra_attrs`]) and applies them for the flames JWildfire's renderer draws.
//!
//! The facts are JWildfire 9.00's (`XForm`, `TransformationAffineFullStep`,
//! `TransformationPostAffineStep`): a plane's map counts when one of its six numbers differs
//! from the identity's by more than 10⁻⁸. The linear parts apply in turn — xy, then yz on
//! (y, z), then zx on (x, z) — and the translations of all three are added at the end: x gets
//! the xy and zx offsets' first numbers, y the xy offset's second and the yz offset's first,
//! z the yz and zx offsets' second numbers.

use crate::flame::model::{Affine, Xform};

/// The maps of the yz and zx planes at one place of an xform (before or after the
/// variations); `None`: the plane's map is the identity.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Planes {
    /// The map of (y, z), in the letters of [`Affine`] with y as its x and z as its y.
    pub yz: Option<Affine>,
    /// The map of (x, z), with x as its x and z as its y.
    pub zx: Option<Affine>,
}

/// An xform's plane maps before and after its variations.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct XformPlanes {
    /// With the affine map (`coefs`).
    pub pre: Option<Planes>,
    /// With the post map (`post`).
    pub post: Option<Planes>,
}

/// JWildfire's test of a map: some number differs from the identity's by more than 10⁻⁸.
fn counts(m: &Affine) -> bool {
    let id = Affine::IDENTITY;
    [
        (m.a, id.a),
        (m.b, id.b),
        (m.c, id.c),
        (m.d, id.d),
        (m.e, id.e),
        (m.f, id.f),
    ]
    .iter()
    .any(|(v, w)| (v - w).abs() > 1e-8)
}

/// The map an attribute of `x` names (six numbers), if it counts.
fn plane(x: &Xform, name: &str) -> Option<Affine> {
    let (_, v) = x.extra_attrs.iter().find(|(k, _)| k == name)?;
    let mut n = [0.0; 6];
    let mut it = v.split_whitespace();
    for slot in &mut n {
        *slot = it.next()?.parse::<f64>().ok()?;
    }
    if it.next().is_some() {
        return None;
    }
    let m = Affine::from_coefs(n);
    counts(&m).then_some(m)
}

impl XformPlanes {
    /// The plane maps of `x`; `None` when it has none that counts.
    pub fn of(x: &Xform) -> Option<XformPlanes> {
        let side = |yz: &str, zx: &str| {
            let p = Planes {
                yz: plane(x, yz),
                zx: plane(x, zx),
            };
            (p.yz.is_some() || p.zx.is_some()).then_some(p)
        };
        let planes = XformPlanes {
            pre: side("yzCoefs", "zxCoefs"),
            post: side("yzPostCoefs", "zxPostCoefs"),
        };
        (planes.pre.is_some() || planes.post.is_some()).then_some(planes)
    }
}

impl Planes {
    /// The image of (x, y, z) under the xy map `xy` and these plane maps, as JWildfire
    /// composes them.
    #[inline(always)]
    pub fn apply(&self, xy: &Affine, x: f64, y: f64, z: f64) -> (f64, f64, f64) {
        let (mut px, mut py, mut pz) = (xy.a * x + xy.b * y, xy.c * x + xy.d * y, z);
        let (mut ox, mut oy, mut oz) = (xy.e, xy.f, 0.0);
        if let Some(m) = &self.yz {
            (py, pz) = (m.a * py + m.b * pz, m.c * py + m.d * pz);
            oy += m.e;
            oz += m.f;
        }
        if let Some(m) = &self.zx {
            (px, pz) = (m.a * px + m.b * pz, m.c * px + m.d * pz);
            ox += m.e;
            oz += m.f;
        }
        (px + ox, py + oy, pz + oz)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn with(attrs: &[(&str, &str)]) -> Xform {
        Xform {
            extra_attrs: attrs
                .iter()
                .map(|(k, v)| (k.to_string(), v.to_string()))
                .collect(),
            ..Xform::default()
        }
    }

    /// A quarter turn of the zx plane (x ↦ −z, z ↦ x: JWildfire's numbers 0 1 −1 0 as
    /// `zx00 zx01 zx10 zx11`), after the xy map, with every offset added at the end.
    #[test]
    fn a_zx_turn_follows_the_xy_map_and_offsets_come_last() {
        let x = with(&[("zxCoefs", "0.0 1.0 -1.0 0.0 0.25 -0.5")]);
        let planes = XformPlanes::of(&x).unwrap();
        assert_eq!(planes.post, None);
        let pre = planes.pre.unwrap();
        assert_eq!(pre.yz, None);
        // xy: x' = 2x + 0.3 (offset), y' = 3y − 0.1.
        let xy = Affine::new(2.0, 0.0, 0.0, 3.0, 0.3, -0.1);
        let (x1, y1, z1) = pre.apply(&xy, 0.5, 0.25, 0.75);
        // Linear parts: (1.0, 0.75, 0.75); zx: x = −z = −0.75, z = x = 1.0.
        assert_eq!((x1, y1, z1), (-0.75 + (0.3 + 0.25), 0.75 - 0.1, 1.0 - 0.5));
    }

    /// The yz map acts on (y, z) before the zx map acts on (x, z).
    #[test]
    fn yz_then_zx() {
        let x = with(&[
            ("yzCoefs", "1.0 0.5 0.0 1.0 0.0 0.0"),
            ("zxCoefs", "1.0 0.0 2.0 1.0 0.0 0.0"),
        ]);
        let pre = XformPlanes::of(&x).unwrap().pre.unwrap();
        // yz: y' = y, z' = 0.5y + z; zx: x' = x + 2z', z'' = z'.
        let (x1, y1, z1) = pre.apply(&Affine::IDENTITY, 1.0, 2.0, 3.0);
        assert_eq!((x1, y1, z1), (1.0 + 2.0 * 4.0, 2.0, 4.0));
    }

    /// Maps within 10⁻⁸ of the identity, malformed ones and missing ones do not count.
    #[test]
    fn identity_and_malformed_maps_do_not_count() {
        for attrs in [
            vec![],
            vec![("zxCoefs", "1.0 0.0 0.0 1.0 0.0 0.0")],
            vec![("yzCoefs", "1.000000001 0.0 0.0 1.0 0.0 5e-9")],
            vec![("zxCoefs", "0.5 0.0 0.0 1.0 0.0")],
            vec![("zxCoefs", "0.5 0.0 0.0 1.0 0.0 0.0 7")],
            vec![("yzPostCoefs", "x 0.0 0.0 1.0 0.0 0.0")],
        ] {
            assert_eq!(XformPlanes::of(&with(&attrs)), None, "{attrs:?}");
        }
        let post = with(&[("yzPostCoefs", "1.0 0.0 0.0 1.0 0.0 0.1")]);
        let p = XformPlanes::of(&post).unwrap();
        assert_eq!(p.pre, None);
        assert!(p.post.unwrap().yz.is_some());
    }
}
