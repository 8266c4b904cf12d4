//! The 3-D IFS of Fractint `(3D)` entries: chaos game in space, fixed view rotation and
//! orthographic projection onto the image plane (y up in Fractint, so y is negated).

use crate::flame::chaos::{CHOOSE_GRAIN, FUSE, selection_table};
use crate::flame::model::{Flame, Ifs3d};
use crate::flame::rng::FastRng;

/// A 3-D IFS ready to iterate.
#[derive(Clone, Debug)]
pub struct Ifs3dSystem {
    maps: Vec<[f64; 12]>,
    colors: Vec<f64>,
    table: Box<[u16]>,
    /// View rotation (row-major 3×3), applied before projecting.
    view: [[f64; 3]; 3],
}

impl Ifs3dSystem {
    pub fn new(ifs: &Ifs3d) -> Option<Ifs3dSystem> {
        if ifs.rows.is_empty() {
            return None;
        }
        let n = ifs.rows.len();
        let p: Vec<f64> = ifs.rows.iter().map(|r| r[12].max(0.0)).collect();
        let sum: f64 = p.iter().sum();
        let weights = if sum > 0.0 { p } else { vec![1.0; n] };
        let [ax, ay, az] = ifs.view_degrees.map(f64::to_radians);
        let rx = [
            [1.0, 0.0, 0.0],
            [0.0, ax.cos(), -ax.sin()],
            [0.0, ax.sin(), ax.cos()],
        ];
        let ry = [
            [ay.cos(), 0.0, ay.sin()],
            [0.0, 1.0, 0.0],
            [-ay.sin(), 0.0, ay.cos()],
        ];
        let rz = [
            [az.cos(), -az.sin(), 0.0],
            [az.sin(), az.cos(), 0.0],
            [0.0, 0.0, 1.0],
        ];
        let view = mat_mul(&rz, &mat_mul(&ry, &rx));
        Some(Ifs3dSystem {
            maps: ifs
                .rows
                .iter()
                .map(|r| r[..12].try_into().expect("12"))
                .collect(),
            colors: (0..n)
                .map(|i| {
                    if n > 1 {
                        i as f64 / (n - 1) as f64
                    } else {
                        0.0
                    }
                })
                .collect(),
            table: selection_table(&weights),
            view,
        })
    }

    /// Project a point of space to world (x, y) of the flame plane (y down).
    #[inline(always)]
    pub fn project(&self, p: [f64; 3]) -> (f64, f64) {
        let v = &self.view;
        let x = v[0][0] * p[0] + v[0][1] * p[1] + v[0][2] * p[2];
        let y = v[1][0] * p[0] + v[1][1] * p[1] + v[1][2] * p[2];
        (x, -y)
    }

    /// Run `n` plotted samples from a random start (fused), like the 2-D chaos game.
    pub fn run_sub_batch<F: FnMut(f64, f64, f64, f64)>(
        &self,
        n: u64,
        rng: &mut FastRng,
        mut plot: F,
    ) -> u64 {
        let mut p = [rng.f11(), rng.f11(), rng.f11()];
        let mut c = rng.f01();
        let mut bad = 0;
        let mut k = -FUSE;
        while k < n as i64 {
            let i = self.table[rng.u32() as usize & (CHOOSE_GRAIN - 1)] as usize;
            let m = &self.maps[i];
            let q = [
                m[0] * p[0] + m[1] * p[1] + m[2] * p[2] + m[9],
                m[3] * p[0] + m[4] * p[1] + m[5] * p[2] + m[10],
                m[6] * p[0] + m[7] * p[1] + m[8] * p[2] + m[11],
            ];
            c = 0.5 * self.colors[i] + 0.5 * c;
            if q.iter().all(|v| v.abs() <= 1e10) {
                p = q;
            } else {
                bad += 1;
                p = [rng.f11(), rng.f11(), rng.f11()];
            }
            if k >= 0 {
                let (x, y) = self.project(p);
                plot(x, y, c, 1.0);
            }
            k += 1;
        }
        bad
    }
}

fn mat_mul(a: &[[f64; 3]; 3], b: &[[f64; 3]; 3]) -> [[f64; 3]; 3] {
    let mut m = [[0.0; 3]; 3];
    for i in 0..3 {
        for j in 0..3 {
            m[i][j] = (0..3).map(|k| a[i][k] * b[k][j]).sum();
        }
    }
    m
}

/// The framing orbit of a flame's 3-D IFS (projected points).
pub fn framing_points(flame: &Flame, n: usize) -> Option<(Vec<f64>, Vec<f64>)> {
    let sys = Ifs3dSystem::new(flame.ifs3d.as_ref()?)?;
    let mut rng = FastRng::new(12346);
    let mut xs = Vec::with_capacity(n);
    let mut ys = Vec::with_capacity(n);
    sys.run_sub_batch(n as u64, &mut rng, |x, y, _, _| {
        xs.push(x);
        ys.push(y);
    });
    Some((xs, ys))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn view_is_a_rotation_and_projection_flips_y() {
        let s = Ifs3dSystem::new(&Ifs3d {
            rows: vec![[
                0.5, 0.0, 0.0, 0.0, 0.5, 0.0, 0.0, 0.0, 0.5, 0.0, 0.0, 0.0, 1.0,
            ]],
            view_degrees: [0.0, 0.0, 0.0],
        })
        .unwrap();
        assert_eq!(s.project([1.0, 2.0, 3.0]), (1.0, -2.0));
        let s = Ifs3dSystem::new(&Ifs3d {
            rows: vec![[0.5; 13]],
            view_degrees: Ifs3d::FRACTINT_VIEW,
        })
        .unwrap();
        // Rows of a rotation are orthonormal.
        for i in 0..3 {
            for j in 0..3 {
                let d: f64 = (0..3).map(|k| s.view[i][k] * s.view[j][k]).sum();
                assert!((d - if i == j { 1.0 } else { 0.0 }).abs() < 1e-12);
            }
        }
    }

    #[test]
    fn the_3d_fern_stays_in_its_box() {
        // Known bounds of the 3-D fern: x [−1.623, 1.623], y [0.044, 7.997], z [−4.999, 0].
        let rows = vec![
            [
                0.0, 0.0, 0.0, 0.0, 0.18, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.01,
            ],
            [
                0.85, 0.0, 0.0, 0.0, 0.85, 0.1, 0.0, -0.1, 0.85, 0.0, 1.6, 0.0, 0.85,
            ],
            [
                0.2, -0.2, 0.0, 0.2, 0.2, 0.0, 0.0, 0.0, 0.3, 0.0, 0.8, 0.0, 0.07,
            ],
            [
                -0.2, 0.2, 0.0, 0.2, 0.2, 0.0, 0.0, 0.0, 0.3, 0.0, 0.8, 0.0, 0.07,
            ],
        ];
        let s = Ifs3dSystem::new(&Ifs3d {
            rows,
            view_degrees: [0.0, 0.0, 0.0],
        })
        .unwrap();
        let mut rng = FastRng::new(3);
        let (mut xmin, mut xmax, mut ymin, mut ymax) = (f64::MAX, f64::MIN, f64::MAX, f64::MIN);
        s.run_sub_batch(200_000, &mut rng, |x, y, _, _| {
            xmin = xmin.min(x);
            xmax = xmax.max(x);
            ymin = ymin.min(-y);
            ymax = ymax.max(-y);
        });
        assert!(xmin > -1.64 && xmax < 1.64 && xmax > 1.55, "{xmin} {xmax}");
        assert!(ymin > -0.01 && ymax < 8.01 && ymax > 7.9, "{ymin} {ymax}");
    }
}
