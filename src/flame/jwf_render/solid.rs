//! JWildfire's solid rendering settings (`sld_render_*`): a flame drawn as a solid object, each
//! pixel showing the nearest point plotted there, lit by distant lights through materials,
//! darkened by screen-space ambient occlusion. The facts come from JWildfire 9.00's
//! `SolidRenderSettings`, `MaterialSettings`, `DistantLight`, `LightDiffFuncPreset` and
//! `LightViewCalculator`; the drawing is in [`super::solid_draw`].

/// How a material's diffuse (and specular) response follows the cosine of the angle between
/// the light and the normal (JWildfire's `LightDiffFuncPreset`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum JwfLightDiff {
    /// cos a.
    #[default]
    Cosa,
    /// cos² a.
    CosaSquare,
    /// (cos a)/2 + 1/2.
    CosaHalve,
    /// ((cos a)/2 + 1/2)².
    CosaHalveSquare,
}

impl JwfLightDiff {
    /// Every function, in JWildfire's order.
    pub const ALL: [JwfLightDiff; 4] = [
        JwfLightDiff::Cosa,
        JwfLightDiff::CosaSquare,
        JwfLightDiff::CosaHalve,
        JwfLightDiff::CosaHalveSquare,
    ];

    /// The name JWildfire writes.
    pub fn name(self) -> &'static str {
        match self {
            JwfLightDiff::Cosa => "COSA",
            JwfLightDiff::CosaSquare => "COSA_SQUARE",
            JwfLightDiff::CosaHalve => "COSA_HALVE",
            JwfLightDiff::CosaHalveSquare => "COSA_HALVE_SQUARE",
        }
    }

    /// The function JWildfire names `s`.
    pub fn from_name(s: &str) -> Option<Self> {
        Self::ALL.into_iter().find(|k| k.name() == s)
    }

    /// The response to cosine `c`.
    #[inline]
    pub fn eval(self, c: f64) -> f64 {
        match self {
            JwfLightDiff::Cosa => c,
            JwfLightDiff::CosaSquare => c * c,
            JwfLightDiff::CosaHalve => c * 0.5 + 0.5,
            JwfLightDiff::CosaHalveSquare => {
                let h = c * 0.5 + 0.5;
                h * h
            }
        }
    }
}

/// One material of a solid flame (JWildfire's `MaterialSettings`).
#[derive(Clone, Debug, PartialEq)]
pub struct JwfMaterial {
    /// Strength of the lights' diffuse response.
    pub diffuse: f64,
    /// Strength of the object's own colour.
    pub ambient: f64,
    /// Strength of the specular highlight.
    pub phong: f64,
    /// Exponent of the specular highlight.
    pub phong_size: f64,
    /// Colour of the specular highlight (RGB, 0–1).
    pub phong_color: [f64; 3],
    /// The response to the angle of the light.
    pub light_diff: JwfLightDiff,
    /// Reflection map: strength, image file and mapping name (`BLINN_NEWELL`, `SPHERICAL`).
    /// ugnis does not draw reflection maps; they are kept for writing back.
    pub refl_map_intensity: f64,
    /// The reflection map's image file.
    pub refl_map_filename: String,
    /// The reflection map's mapping.
    pub refl_mapping: String,
}

impl Default for JwfMaterial {
    fn default() -> Self {
        JwfMaterial {
            diffuse: 0.5,
            ambient: 1.0,
            phong: 1.0,
            phong_size: 24.0,
            phong_color: [0.0; 3],
            light_diff: JwfLightDiff::Cosa,
            refl_map_intensity: 0.5,
            refl_map_filename: String::new(),
            refl_mapping: "BLINN_NEWELL".into(),
        }
    }
}

/// One distant light of a solid flame (JWildfire's `DistantLight`).
#[derive(Clone, Debug, PartialEq)]
pub struct JwfLight {
    /// Degrees.
    pub altitude: f64,
    /// Degrees.
    pub azimuth: f64,
    /// Strength.
    pub intensity: f64,
    /// RGB, 0–1.
    pub color: [f64; 3],
    /// Whether the light casts shadows (not drawn).
    pub cast_shadows: bool,
    /// How dark its shadows are (not drawn).
    pub shadow_intensity: f64,
}

impl Default for JwfLight {
    fn default() -> Self {
        JwfLight {
            altitude: 0.0,
            azimuth: 0.0,
            intensity: 0.5,
            color: [0.0; 3],
            cast_shadows: true,
            shadow_intensity: 0.8,
        }
    }
}

impl JwfLight {
    /// The direction the light travels in, as JWildfire's `LightViewCalculator` gives it: the
    /// view axis (0, 0, −1) turned back by the altitude about x and the azimuth about y.
    pub fn direction(&self) -> [f64; 3] {
        let (sa, ca) = (-self.altitude).to_radians().sin_cos();
        let (sb, cb) = (-self.azimuth).to_radians().sin_cos();
        // The third row of the light's turn, negated.
        [ca * sb, -sa, -ca * cb]
    }
}

/// Most materials or lights read from a file.
pub const MAX_SOLID_ITEMS: usize = 64;

/// JWildfire's solid rendering settings, with its defaults.
#[derive(Clone, Debug, PartialEq)]
pub struct JwfSolid {
    /// Draw the flame solid (`sld_render_enabled`).
    pub enabled: bool,
    /// Ambient occlusion on.
    pub ao_enabled: bool,
    /// How much the occlusion darkens the ambient light.
    pub ao_intensity: f64,
    /// How far it looks, in 1/500 of the raster's diagonal.
    pub ao_search_radius: f64,
    /// How far it is smoothed, in 1/500 of the raster's diagonal.
    pub ao_blur_radius: f64,
    /// Steps along each direction.
    pub ao_radius_samples: u32,
    /// Directions.
    pub ao_azimuth_samples: u32,
    /// How fast an occluder's weight falls with its distance.
    pub ao_falloff: f64,
    /// Share of the occlusion that also darkens the diffuse light.
    pub ao_affect_diffuse: f64,
    /// `OFF`, `FAST` or `SMOOTH` (ugnis draws no shadows; kept for writing back).
    pub shadow_type: String,
    /// Shadow settings (not drawn; kept for writing back).
    pub shadow_smooth_radius: f64,
    /// Shadow settings (not drawn; kept for writing back).
    pub shadowmap_size: u32,
    /// Shadow settings (not drawn; kept for writing back).
    pub shadowmap_bias: f64,
    /// The materials, by material coordinate.
    pub materials: Vec<JwfMaterial>,
    /// The lights.
    pub lights: Vec<JwfLight>,
}

impl Default for JwfSolid {
    fn default() -> Self {
        let material = JwfMaterial {
            ambient: 0.5,
            diffuse: 0.7,
            phong: 0.6,
            phong_size: 24.0,
            phong_color: [1.0; 3],
            ..JwfMaterial::default()
        };
        let key = JwfLight {
            altitude: 55.0,
            azimuth: -22.0,
            intensity: 0.8,
            color: [1.0; 3],
            cast_shadows: true,
            shadow_intensity: 0.8,
        };
        let fill = JwfLight {
            altitude: 64.0,
            azimuth: 55.0,
            intensity: 0.6,
            color: [1.0; 3],
            cast_shadows: false,
            shadow_intensity: 0.7,
        };
        JwfSolid {
            enabled: false,
            ao_enabled: true,
            ao_intensity: 0.6,
            ao_search_radius: 4.0,
            ao_blur_radius: 1.5,
            ao_radius_samples: 6,
            ao_azimuth_samples: 7,
            ao_falloff: 0.5,
            ao_affect_diffuse: 0.1,
            shadow_type: "OFF".into(),
            shadow_smooth_radius: 1.0,
            shadowmap_size: 2048,
            shadowmap_bias: 0.01,
            materials: vec![material],
            lights: vec![key, fill],
        }
    }
}

impl JwfSolid {
    /// The material of material coordinate `m` (JWildfire's `getInterpolatedMaterial`): none
    /// for a negative one, the last beyond the list, a blend of neighbours in between (the
    /// last blends with the first).
    pub fn material(&self, m: f64) -> Option<JwfMaterial> {
        if m.is_nan() || m < 0.0 || self.materials.is_empty() {
            return None;
        }
        let n = self.materials.len();
        let from = m.trunc();
        if from >= n as f64 {
            return self.materials.last().cloned();
        }
        let from = from as usize;
        let to = if from + 1 >= n { 0 } else { from + 1 };
        let t = m - m.trunc();
        const EPS: f64 = 0.01;
        if t < EPS {
            return self.materials.get(from).cloned();
        }
        if t > 1.0 - EPS {
            return self.materials.get(to).cloned();
        }
        let (a, b) = (&self.materials[from], &self.materials[to]);
        let mix = |x: f64, y: f64| x + (y - x) * t;
        Some(JwfMaterial {
            // JWildfire's blend takes the diffuse strength from the reflection maps'.
            diffuse: mix(a.refl_map_intensity, b.refl_map_intensity),
            ambient: mix(a.ambient, b.ambient),
            phong: mix(a.phong, b.phong),
            phong_size: mix(a.phong_size, b.phong_size),
            phong_color: [0, 1, 2].map(|k| mix(a.phong_color[k], b.phong_color[k])),
            light_diff: if t < 0.5 { a.light_diff } else { b.light_diff },
            refl_map_intensity: mix(a.refl_map_intensity, b.refl_map_intensity),
            refl_map_filename: String::new(),
            refl_mapping: a.refl_mapping.clone(),
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A light straight above the view axis (altitude 90°) shines down the y axis; at altitude
    /// 0 and azimuth 0 it shines along the view axis, into the picture.
    #[test]
    fn light_directions() {
        let d = |alt: f64, az: f64| {
            JwfLight {
                altitude: alt,
                azimuth: az,
                ..JwfLight::default()
            }
            .direction()
        };
        let close = |a: [f64; 3], b: [f64; 3]| a.iter().zip(b).all(|(x, y)| (x - y).abs() < 1e-12);
        assert!(close(d(0.0, 0.0), [0.0, 0.0, -1.0]));
        assert!(close(d(90.0, 0.0), [0.0, 1.0, 0.0]));
        assert!(close(d(0.0, 90.0), [-1.0, 0.0, 0.0]));
        let v = d(55.0, -22.0);
        assert!((v.iter().map(|x| x * x).sum::<f64>() - 1.0).abs() < 1e-12);
    }

    #[test]
    fn materials_by_coordinate() {
        let mut s = JwfSolid::default();
        let mut second = s.materials[0].clone();
        second.ambient = 0.1;
        s.materials.push(second);
        assert_eq!(s.material(-0.5), None);
        assert_eq!(s.material(f64::NAN), None);
        assert_eq!(s.material(0.0).unwrap().ambient, 0.5);
        assert_eq!(s.material(1.0).unwrap().ambient, 0.1);
        assert_eq!(s.material(7.0).unwrap().ambient, 0.1);
        assert!((s.material(0.25).unwrap().ambient - 0.4).abs() < 1e-12);
        // The last blends with the first.
        assert!((s.material(1.5).unwrap().ambient - 0.3).abs() < 1e-12);
    }
}
