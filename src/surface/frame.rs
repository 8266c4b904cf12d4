//! From the colour buffers of the eyes to the picture: a stereo pair's halves side by side, the
//! supersampled pixels averaged, 8-bit RGB.

use glam::Vec3;
use image::RgbImage;

use super::eye::{Eye, eyes};
use super::scene::Scene;

/// The picture of a scene: every eye rendered by `render_eye` (eye, width, height) into a
/// colour buffer at the supersampled size, a stereo pair's left eye on the left half, then
/// averaged down to the scene's size. None when an eye was cancelled.
pub(crate) fn picture(
    scene: &Scene,
    render_eye: impl Fn(&Eye, usize, usize) -> Option<Vec<Vec3>>,
) -> Option<RgbImage> {
    let ss = scene.supersample.clamp(1, 4) as usize;
    let (w, h, eyes) = eyes(scene);
    if let [(left_eye, half), (right_eye, _)] = eyes.as_slice() {
        let half = *half;
        let left = render_eye(left_eye, half, h)?;
        let right = render_eye(right_eye, half, h)?;
        let mut buf = vec![scene.background; w * h];
        for y in 0..h {
            buf[y * w..y * w + half].copy_from_slice(&left[y * half..(y + 1) * half]);
            buf[y * w + half..y * w + 2 * half].copy_from_slice(&right[y * half..(y + 1) * half]);
        }
        return Some(to_image(&buf, w, h, ss));
    }
    let (eye, _) = &eyes[0];
    let buf = render_eye(eye, w, h)?;
    Some(to_image(&buf, w, h, ss))
}

/// Average `ss`×`ss` blocks of the `w`×`h` linear buffer into 8-bit RGB pixels.
fn to_image(buf: &[Vec3], w: usize, h: usize, ss: usize) -> RgbImage {
    let (ow, oh) = (w / ss, h / ss);
    let mut img = RgbImage::new(ow as u32, oh as u32);
    let n = (ss * ss) as f32;
    for y in 0..oh {
        for x in 0..ow {
            let mut c = Vec3::ZERO;
            for dy in 0..ss {
                for dx in 0..ss {
                    c += buf[(y * ss + dy) * w + x * ss + dx];
                }
            }
            let c = (c / n).clamp(Vec3::ZERO, Vec3::ONE) * 255.0 + Vec3::splat(0.5);
            img.put_pixel(
                x as u32,
                y as u32,
                image::Rgb([c.x as u8, c.y as u8, c.z as u8]),
            );
        }
    }
    img
}
