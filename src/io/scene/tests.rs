//! Tests of scene files: full scenes, ray casting objects, and the diagnostics of bad ones.

use glam::Vec3;

use super::*;
use crate::surface::{Projection, Renderer, SliceAxis};

#[test]
fn parses_a_full_scene() {
    let text = r#"
[image]
size = [320, 240]
background = [0.1, 0.1, 0.1]
[camera]
target = [0, 1, 0]
distance = 6
azimuth = 20
polar = 70
projection = "isometric"
[lighting]
ambient = 0.8
[[light]]
position = [1, 5, 5]
intensity = [4, 4, 3]
[[texture]]
name = "noise"
kind = "fbm"
size = [64, 64]
[[texture]]
name = "cells"
kind = "mrf"
size = [32, 32]
sweeps = 5
[[object]]
kind = "jug"
texture = "noise"
material = { ks = 0.5, n = 40, bump = 0.01 }
transform = [{ rotate_y = 30 }, { translate = [0, 0.1, 0] }]
[[object]]
kind = "bezier"
degree = [1, 1]
net = [[0,0,0],[0,0,1],[1,0,0],[1,0,1]]
texture = "cells"
"#;
    let s = parse(text, "t.toml", Path::new(".")).unwrap();
    assert_eq!(s.scene.objects.len(), 2);
    assert_eq!(s.texture_names, vec!["noise", "cells"]);
    assert_eq!((s.scene.width, s.scene.height), (320, 240));
    assert!(matches!(
        s.scene.camera.projection,
        Projection::Axonometric { .. }
    ));
    assert_eq!(s.scene.objects[0].material.shininess, 40.0);
    assert_eq!(s.scene.lights[0].intensity, Vec3::new(4.0, 4.0, 3.0));
}

#[test]
fn parses_ray_casting_menger_and_quaternion_julia() {
    let text = r#"
render = "raycast"
shadows = false
[[object]]
kind = "menger"
step = 2
size = 3
[[object]]
kind = "quaternion_julia"
c = [-0.2, 0.8, 0.1, 0.0]
slice = "j"
slice_value = 0.25
iterations = 9
[[object]]
kind = "qjulia"
c = [-1, 0.2]
"#;
    let s = parse(text, "t.toml", Path::new(".")).unwrap().scene;
    assert_eq!(s.renderer, Renderer::RayCast);
    assert!(!s.shadows);
    let Geometry::Mesh(m) = &s.objects[0].geometry else {
        panic!("menger is a mesh")
    };
    // Edge 3: the corners lie at ±1.5.
    let max = m
        .positions
        .iter()
        .map(|p| p.abs().max_element())
        .fold(0.0, f64::max);
    assert_eq!(max, 1.5);
    let Geometry::QuaternionJulia(j) = &s.objects[1].geometry else {
        panic!("quaternion julia")
    };
    assert_eq!(j.c, [-0.2, 0.8, 0.1, 0.0]);
    assert_eq!(
        (j.slice, j.slice_value, j.iterations),
        (SliceAxis::J, 0.25, 9)
    );
    let Geometry::QuaternionJulia(j) = &s.objects[2].geometry else {
        panic!("quaternion julia")
    };
    assert_eq!(j.c, [-1.0, 0.2, 0.0, 0.0]);
    // Defaults: the z-buffer, shadows on for when ray casting is chosen.
    let d = parse("", "d.toml", Path::new(".")).unwrap().scene;
    assert_eq!((d.renderer, d.shadows), (Renderer::ZBuffer, true));
    // A bad render value points at its line.
    let e = parse("\nrender = 3\n", "s.toml", Path::new("."))
        .err()
        .unwrap();
    assert_eq!(e.code, "SCN001");
    let e = parse("\n\nrender = \"x\"\n", "s.toml", Path::new("."))
        .err()
        .unwrap();
    assert_eq!(e.pos, Pos::LineCol(3, 10), "{e}");
}

#[test]
fn bad_scenes_say_where_and_what() {
    for (text, code, want) in [
        ("[image]\nsize = [0, 10]\n", "SCN002", "size"),
        (
            "[[object]]\nkind = \"blob\"\n",
            "SCN005",
            "unknown object kind",
        ),
        (
            "[[object]]\nkind = \"jug\"\ntexture = \"nope\"\n",
            "SCN005",
            "no texture named",
        ),
        (
            "[[texture]]\nname = \"a\"\nkind = \"image\"\nfile = \"missing.png\"\n",
            "SCN004",
            "does not exist",
        ),
        (
            "[camera]\nprojection = \"fisheye\"\n",
            "SCN002",
            "projection",
        ),
        (
            "[[object]]\nkind = \"revolve\"\nprofile = [[0,0],[1,1]]\n",
            "SCN005",
            "3k + 1",
        ),
        ("[image]\nsize = [10, 10\n", "SCN001", ""),
        ("[image]\nbackground = [0, -inf, 0]\n", "SCN001", "'-inf'"),
        (
            "# nan = inf\n[[light]]\nposition = [1, 2, 3]\nintensity = nan\n",
            "SCN001",
            "'nan'",
        ),
        ("[image]\nsizes = [10, 10]\n", "SCN001", "sizes"),
        (
            "render = \"pathtrace\"\n",
            "SCN002",
            "expected \"zbuffer\" or \"raycast\"",
        ),
        ("shadows = true\n", "SCN002", "needs render = \"raycast\""),
        (
            "[[object]]\nkind = \"menger\"\nstep = 5\n",
            "SCN005",
            "step 5 is too deep: expected 0 to 4",
        ),
        (
            "[[object]]\nkind = \"menger\"\nsize = -1\n",
            "SCN005",
            "size -1",
        ),
        (
            "[[object]]\nkind = \"quaternion_julia\"\nc = [1, 2, 3]\n",
            "SCN005",
            "c has 3 numbers",
        ),
        (
            "[[object]]\nkind = \"qjulia\"\niterations = 0\n",
            "SCN005",
            "iterations 0 must be between 1 and 200",
        ),
        (
            "[[object]]\nkind = \"qjulia\"\nslice = \"w\"\n",
            "SCN005",
            "slice 'w'",
        ),
        (
            "[[object]]\nkind = \"qjulia\"\nc = [9, 0]\n",
            "SCN005",
            "|c| = 9",
        ),
    ] {
        let e = parse(text, "s.toml", Path::new("/nonexistent"))
            .err()
            .unwrap_or_else(|| panic!("{text}"));
        assert_eq!(e.code, code, "{text}: {e}");
        assert!(e.to_string().contains(want), "{text}: {e}");
        assert!(e.to_string().contains("s.toml"));
    }
    let e = parse("[image]\n\nsize = \"big\"\n", "s.toml", Path::new("."))
        .err()
        .unwrap();
    assert_eq!(e.pos, Pos::LineCol(3, 8), "{e}");
}
