//! The L-systems of the teaching sources as ready-made presets: each with the order it is shown
//! at and a note on where it comes from.

use super::system::{Angle, LSystem};

/// A ready-made system with the order it is shown at and a note on its source.
#[derive(Clone, Debug, PartialEq)]
pub struct Preset {
    /// The L-system.
    pub system: LSystem,
    /// The order (number of rewriting steps) it is shown at.
    pub order: u32,
    /// Where it comes from and what it shows (may be empty).
    pub note: &'static str,
}

fn sys(name: &str, axiom: &str, rules: &[(char, &str)], angle: Angle) -> LSystem {
    LSystem::new(name, axiom, rules, angle)
}

/// The Koch curve: `F` → `F+F--F+F` with δ = 60°, order 4.
pub fn koch_curve() -> Preset {
    Preset {
        system: sys("Koch curve", "F", &[('F', "F+F--F+F")], Angle::Divisions(6)),
        order: 4,
        note: "4ⁿ segments of length 3⁻ⁿ; D = log 4/log 3 = 1.26186",
    }
}

/// Kovács' Koch variant `S` → `S+S-S-S+S`, order 3.
pub fn koch_kovacs() -> Preset {
    let mut s = sys(
        "Koch (Kovács)",
        "S",
        &[('S', "S+S-S-S+S")],
        Angle::Degrees(90.0),
    );
    s.draw_symbols = "S".into();
    Preset {
        system: s,
        order: 3,
        note: "With 90° turns this is the quadratic Koch curve, D = log 5/log 3 = 1.46497 \
               (the article quotes 1.261, the value of the 60° Koch curve).",
    }
}

/// Kovács' fractal plant, order 5.
pub fn plant_kovacs() -> Preset {
    let mut s = sys(
        "Fractal plant (Kovács)",
        "S",
        &[('S', "F-[[S]+S]+F[+FS]-S"), ('F', "FF")],
        Angle::Degrees(25.0),
    );
    s.swap_signs = true;
    s.start_heading = 90.0;
    Preset {
        system: s,
        order: 5,
        note: "Lindenmayer's fractal plant (the article calls it the Barnsley fern, which is \
               an IFS). Its − turns left, so + and − are swapped here; S draws nothing.",
    }
}

/// A graftal of 0s and 1s with branches, order 5.
pub fn graftal() -> Preset {
    let mut s = sys(
        "Graftal (Kovács)",
        "0",
        &[('0', "1[0]1[0]0"), ('1', "11")],
        Angle::Degrees(45.0),
    );
    s.draw_symbols = "01".into();
    s.bracket_turn = true;
    s.start_heading = 90.0;
    Preset {
        system: s,
        order: 5,
        note: "0 and 1 draw a step; [ saves the turtle and turns by δ, so every branch turns \
               the same way. The article gives neither axiom nor angle (0 and 45° assumed).",
    }
}

/// The Fibonacci strings b, a, ab, aba, … (draws nothing), order 7.
pub fn fibonacci() -> Preset {
    Preset {
        system: sys(
            "Fibonacci",
            "b",
            &[('a', "ab"), ('b', "a")],
            Angle::Degrees(90.0),
        ),
        order: 7,
        note: "Draws nothing: the lengths of the strings b, a, ab, aba, abaab, … are the \
               Fibonacci numbers.",
    }
}

/// The Koch snowflake: axiom `F++F++F`, `F` → `F-F++F-F`, δ = 60°, order 3.
pub fn koch_snowflake() -> Preset {
    Preset {
        system: sys(
            "Koch snowflake",
            "F++F++F",
            &[('F', "F-F++F-F")],
            Angle::Degrees(60.0),
        ),
        order: 3,
        note: "3·4ⁿ segments; the area tends to 8/5 of the triangle's",
    }
}

/// The quadratic Koch island: axiom `F-F-F-F`, `F` → `F+F-F-FF+F+F-F`, δ = 90°, order 2.
pub fn quadratic_koch_island() -> Preset {
    Preset {
        system: sys(
            "Quadratic Koch island",
            "F-F-F-F",
            &[('F', "F+F-F-FF+F+F-F")],
            Angle::Degrees(90.0),
        ),
        order: 2,
        note: "4·8ⁿ segments; the step shrinks 4× per level, D = 1.5",
    }
}

/// The square inner tree: axiom `F+F+F+F`, `F` → `FF+F++F+F`, δ = 90°, order 3.
pub fn square_inner_tree() -> Preset {
    Preset {
        system: sys(
            "Square inner tree",
            "F+F+F+F",
            &[('F', "FF+F++F+F")],
            Angle::Degrees(90.0),
        ),
        order: 3,
        note: "",
    }
}

fn plant(name: &str, rule: &str, deg: f64, order: u32, note: &'static str) -> Preset {
    let mut s = sys(name, "F", &[('F', rule)], Angle::Degrees(deg));
    s.start_heading = 90.0;
    Preset {
        system: s,
        order,
        note,
    }
}

/// Plant (a): `F` → `F[+F]F[-F]F`, δ = 30°, order 5.
pub fn plant_a() -> Preset {
    plant(
        "Plant (a)",
        "F[+F]F[-F]F",
        30.0,
        5,
        "5ⁿ segments; the slides' introductory plant. The book uses 25.7°.",
    )
}

/// Plant (b): `F` → `F[+F]F[-F][F]`, δ = 20°, order 5.
pub fn plant_b() -> Preset {
    plant("Plant (b)", "F[+F]F[-F][F]", 20.0, 5, "")
}

/// Plant (c): `F` → `FF-[-F+F+F]+[+F-F-F]`, δ = 20.5°, order 4.
pub fn plant_c() -> Preset {
    plant(
        "Plant (c)",
        "FF-[-F+F+F]+[+F-F-F]",
        20.5,
        4,
        "The book uses 22.5°.",
    )
}

/// Arborvitae: `F` → `F[+F]F[-F][F]`, δ = 90° as printed, order 4.
pub fn arborvitae() -> Preset {
    plant(
        "Arborvitae",
        "F[+F]F[-F][F]",
        90.0,
        4,
        "90° as the slides print it — probably a misprint for a small angle.",
    )
}

/// Fractint's dragon curve: axiom `FX`, δ = 45°, order 10.
pub fn dragon() -> Preset {
    Preset {
        system: sys(
            "Dragon",
            "FX",
            &[('F', ""), ('y', "+FX--FY+"), ('x', "-FX++FY-")],
            Angle::Divisions(8),
        ),
        order: 10,
        note: "Fractint's example; F= deletes F, so only the last generation's F draw.",
    }
}

/// Every preset, in menu order.
pub fn all() -> Vec<Preset> {
    vec![
        koch_curve(),
        koch_kovacs(),
        koch_snowflake(),
        quadratic_koch_island(),
        square_inner_tree(),
        plant_kovacs(),
        graftal(),
        fibonacci(),
        plant_a(),
        plant_b(),
        plant_c(),
        arborvitae(),
        dragon(),
    ]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_preset_compiles_and_draws() {
        for p in all() {
            let c = p.system.compile().unwrap();
            let n = c.segments(p.order).unwrap().count() as f64;
            assert_eq!(n, c.counts(p.order).segments, "{}", p.system.name);
        }
    }
}
