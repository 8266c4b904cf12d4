//! Variations: the non-linear functions an xform applies after its affine map.
//!
//! One registry holds every variation ugnis knows: flam3's classic list (ids 0–98 in flam3's
//! order, so that flam3's numeric `var` lists keep working), Fractorium's catalogue and the
//! JWildfire variations that real files use. Each entry ([`VarDef`]) names the variation, its
//! parameters with defaults and ranges, which per-point quantities it reads, and its formula.
//!
//! A variation is used in one of three forms ([`Form`]), as Fractorium and JWildfire do:
//! - regular: the outputs of an xform's regular variations are summed;
//! - `pre_NAME`: applied to the affine-transformed point before the regular variations,
//!   replacing it (or adding to it, for the variations whose [`Assign`] is `Sum`);
//! - `post_NAME`: applied to the summed result, replacing (or adding to) it.
//!
//! A formula receives the point as a [`VarIn`] (with r², r, x/r, y/r and both angles computed
//! once for the xform, as flam3 and Fractorium precompute them), the xform's running output as
//! an [`Acc`] (a few variations read or rewrite what earlier variations summed, or set the
//! colour), and returns its own weighted output `[x, y, z]`.
//!
//! Conventions: angles follow flam3 — `atan_xy` = atan2(x, y), `atan_yx` = atan2(y, x) (the usual
//! polar angle); `ux` = x/r, `uy` = y/r, with r replaced by `f64::EPSILON` when it is 0.
//! Fractorium's affine letters A B C D E F are [`Affine`]'s a b e c d f
//! (x' = A·x + B·y + C, y' = D·x + E·y + F).
//!
//! Helpers the formulas share live in `util` (the C/x86 and Java behaviours the source
//! programs rely on, hashes, coordinate systems, complex numbers, special functions) and in
//! `noise` (simplex noise); data that takes long to build (grown aggregates, crystals, meshes,
//! recursive drawings) is built once per parameter values and shared through `shared`.
//!
//! A formula reads its parameters by name, `let [power, dist] = v.params();`, and the values its
//! `prepare` function derived from them, `let [abs_power, cn] = v.derived();` (see
//! [`Prepared::params`]).
//!
//! The framework, by file: `def` (a registry entry and a prepared variation), `params`
//! (parameter kinds and constructors), `point` (what a formula reads and writes), `prepare`
//! (preparing a variation, and evaluating one at one point), `batch` (batches of points),
//! `registry` (the table of every variation, by id) and `names` (attribute names and aliases).
//!
//! The formulas, by origin (`flam3`, `fr_` for Fractorium's catalogue, `jwf_` for JWildfire)
//! and kind:
//!
//! | file | holds |
//! |------|-------|
//! | `flam3` | flam3's 99 classic variations, in flam3's order |
//! | `fr_3d` | 3-D surfaces and 3-D versions of classic shapes (`blob3D`, `bubbleT3D`, `helix`, `taurus`, `cubic3D`, …) |
//! | `fr_bipolar_elliptic` | maps in bipolar (`bCollide`, `bMod`, …) and elliptic (`eJulia`, `eMod`, …) coordinates, `block`, `foci_p` |
//! | `fr_blurs` | blurs filling a shape (`blur3D`, `blur_circle`, `gaussian`, `starblur`, `nBlur`, …) |
//! | `fr_complex` | functions of the complex plane (`arcsech`, `cpow2`, `exp2`, `gamma`, `jac_sn`, `murl`, …) |
//! | `fr_crops` | crops (`crob`, `crop`, `cropn`, `circlecrop`, `hexcrop`, `post_smartcrop`, `vignette`, …) |
//! | `fr_curves` | curves and figures drawn regardless of the input (`Lissajous`, `Spirograph`, `SuperShape3D`, …) |
//! | `fr_direct_colour` | Fractorium's `dc_*` variations and `pixel_flow` |
//! | `fr_distance_blurs` | blurs growing with the distance (`depth_*`, `falloff*`, `farblur`, `rblur`, `blur_zoom`) |
//! | `fr_grids` | square-grid patterns (`checks`, `Voron`, `crackle`, `bwraps`, `squares`, `CircleLinear`, …) |
//! | `fr_hexagons` | hexagonal and triangular tilings (`hexes`, `hex_modulus`, `hexaplay3D`, `xtrb`, …) |
//! | `fr_hyperbolic` | Poincaré-disc tilings and maps (`hypertile*`, `hypershift*`, `poincare*`, `ortho`) |
//! | `fr_inversions` | inversions (`spher`, `roundspher`, `loonie2`, `ovoid`, `GlynnSim*`, `glynnia`, …) |
//! | `fr_julias` | julia-likes: roots with a random branch (`julia3D`, `Juliac`, `julian2`, `juliaq`, `npolar`, …) |
//! | `fr_moves` | linear variants, rotations, shifts, mirrors and flips, the z helpers (`zscale`, `flatten`, …) |
//! | `fr_polynomial_maps` | polynomial and rational maps (`henon`, `lozi`, `q_ode`, `polynomial`, `projective`, …) |
//! | `fr_quaternions` | quaternion functions (`sinq` … `cothq`, `estiq`, `loq`, `mobiq`) |
//! | `fr_radial` | polar warps (`swirl3`, `target`, `circlize`, `smartshape`, the shape family `w`/`x`/`y`/`z`, …) |
//! | `fr_synth` | `synth` |
//! | `fr_trig` | trigonometric formulas of x and y (`bisplit`, `crescents`, `petal`, `rays1`, `tancos`, …) |
//! | `fr_truchet` | Truchet tilings (`Truchet*`, `truchet_knot`, `hex_truchet`) |
//! | `fr_waves` | wave displacements (`waves22` … `waves42`, `ripple`, `vibration`, `interference2`, …) |
//! | `jwf_b_3d` | JWildfire's 3-D maps (`affine3D`, `tangent3D`, `inflateZ_*`, `onion`, …) |
//! | `jwf_b_complex` | JWildfire's complex functions (`cos2_bs`, `acoth`, `sqrt_asinh`, `julia_outside`, `plusrecip`, …) |
//! | `jwf_b_crops` | JWildfire's shape crops (`crop_box`, `crop_x`, `crop_trapezoid`, `crop_polygon`) |
//! | `jwf_b_cuts` | JWildfire's shader cut-outs (`cut_tileillusion`, `cut_sqcir`, `cut_rgrid`, `cut_zigzag`) |
//! | `jwf_b_dc` | JWildfire's shader direct-colour stamps (`dc_acrilic`, `dc_vortex`, `dc_portal`, `glsl_hoshi`) |
//! | `jwf_b_ifs` | small random-map IFS after Paul Bourke (`invtree_js`, `wallpaper_js`, `woggle_js`) |
//! | `jwf_b_shapes` | JWildfire's plane shapes and warps (`waves2_wf`, `yin_yang`, `heart_wf`, …) |
//! | `jwf_a_complex` | JWildfire's complex functions (`sin2_bs` … `sec2_bs`, `acosh`, `sqrt_atanh`, `log_apo`, `joukowski`, …) |
//! | `jwf_a_crops` | JWildfire's crops by shape (`crop_triangle`, `crop_rhombus`, `crop_cross`, `crop_vesica`, `crop3D`) |
//! | `jwf_a_cuts` | JWildfire's cuts along shader patterns (`cut_fun`) |
//! | `jwf_a_dc` | more of JWildfire's `dc_*` stamps (`dc_starsfield`, …) |
//! | `jwf_a_fractals` | JWildfire's escape-time fractals as point sets (`mandelbrot`) |
//! | `jwf_a_ifs` | JWildfire's one-variation IFS with random maps (`dustpoint`, `hadamard_js`, `lace_js`, `apollony`, `siercarpet_js`, …) |
//! | `jwf_a_plane` | JWildfire's maps of the plane by formula (`flower_db`, `atan2_spirals`, `minkQM`, `scrambly`, `colorscale_wf`) |
//! | `jwf_a_sdf3d` | JWildfire's solids filled at random by signed distance (`box3D`, `bbox3D`, `ellipsoid3D`, `pyramid3D`, …) |
//! | `jwf_a_shapes` | JWildfire's figures from the angle, outlined or filled (`cannabiscurve_wf`, `maple_leaf`, …), `cone`, `r_circleblur`, `target_sp`, … |
//! | `jwf_a_surfaces` | JWildfire's 3-D surfaces and z maps (`ennepers2`, `petal3D_apo`, `inflateZ_*`, `onion2`, `boxfold`, …) |
//! | `jwf_a_warps` | JWildfire's warps of the plane (`bwraps7`, `rings3`, `waves3_wf`, `pTransform`, `spligon`, `chunk`, …) |
//! | `jwf_d_crops` | JWildfire's escape-time crops of the summed point (`post_benesi_crop`, `post_aexion_crop`, `post_mandelbox3d_crop`, …) |
//! | `jwf_d_cuts` | more cuts along shader patterns (`cut_spiral`, `cut_wood`, `cut_metaballs`, `cut_truchet`, …) |
//! | `jwf_d_cvar` | a complex function with JWildfire's default code (`c_var`, `pre_c_var`, `post_c_var`, `cut_c`) |
//! | `jwf_d_plane` | cells of the plane (`de_stijl`, `pointgrid_wf`, `pointgrid3d_wf`) |
//! | `jwf_dc_cells` | crackle and hexes coloured by their cell ratio (`dc_crackle_wf`, `dc_cracklep_wf`, `dc_hexes_wf`) |
//! | `jwf_dc_fields` | JWildfire's iterated-field `dc_*` stamps (`dc_layers`, `dc_tree`, `dc_tesla`, `dc_rotations`) |
//! | `jwf_dc_folds` | JWildfire's folding and noise `dc_*` stamps (`dc_ducks`, `dc_mandbrot`, `dc_spacefold`, `dc_warping`, `dc_fractcolor`, `dc_butterflies`) |
//! | `jwf_dc_mandel` | JWildfire's generalised Mandelbrot stamp (`dc_gmandelbroot`) |
//! | `jwf_dc_maps` | JWildfire's direct-colour maps of the plane (`dc_cylinder2`, `dc_dmodulus`, `dc_kaleidotile`, `dc_carpet3D`, `dc_gnarly`) |
//! | `jwf_dc_maths` | GLSL's small functions as JWildfire's shader ports compute them (`step`, the sine hash, the Truchet flip) |
//! | `jwf_dc_patterns` | JWildfire's pattern `dc_*` stamps (`dc_sunflower`, `dc_hexagons`, `dc_fingerprint`, `dc_quadtree`) |
//! | `jwf_dc_tiles` | JWildfire's tiling `dc_*` stamps (`dc_truchet`, `dc_worley`, `dc_pentatiles`, `dc_cairotiles`) |
//! | `jwf_dc_twins` | JWildfire's `dc_*` stamps drawing the patterns of its `glsl_*` ones (`dc_apollonian`, `dc_kaliset`, `dc_squares`, …) |
//! | `jwf_d_solids` | more solids filled at random (`cone3D`, `torus3D`, `capsule3D`, `rbox3D`, …), `hourglass3D`, `gridout3D` |
//! | `jwf_m_crops` | escape-time crops of the summed point (`post_asurf_crop`, `post_mandelbulb3d_crop`) |
//! | `jwf_m_cuts` | still more cuts along shader patterns (`cut_2ewangtile`, `cut_fingerprint`, `cut_kleinian`, …) |
//! | `jwf_m_curves` | curves drawn at random (`maurer_rose`) |
//! | `jwf_m_tilecuts` | cuts along tilings (`cut_hextruchetflow`, `cut_truchetweaving`, `cut_tstruchet`, `cut_triantess`, …) |
//! | `jwf_m_draw` | drawings of many figures, one drawn at random per call (`sunflower`) |
//! | `jwf_h4_cells` | space cut into moved, bent and turned cubes (`cell3D`) |
//! | `jwf_h4_hamid` | Hamid Naderi Yeganeh's figures of segments and circles (`hamid_js`) |
//! | `jwf_h4_ifs` | 74 small iterated function systems (`multi_ifs`) |
//! | `jwf_h4_inversion` | inversion in a circle, conic, polygon, rhodonea or supershape (`inversion`) |
//! | `jwf_h4_kifs` | a kaleidoscopic IFS iterated within one call (`kifs3d`) |
//! | `jwf_h4_klein` | limit sets of Kleinian groups (`klein_group`) |
//! | `jwf_h4_mandala` | Steve Witham's rotation-orbit mandalas (`mandala`, `mandala2`) |
//! | `jwf_h4_metaballs` | points inside seeded metaballs (`metaballs3d_wf`) |
//! | `jwf_h4_recurrence` | recurrence plots of 30 signals (`recurrenceplot`) |
//! | `jwf_h4_shapes` | a cut along Inigo Quilez's 2-D distance functions (`cut_shapes`) |
//! | `jwf_h4_terrain` | a diamond-square landscape mesh (`terrain3D`) |
//! | `jwf_m_foam` | points pushed out of random bubbles (`natural_foam`) |
//! | `jwf_h5_shapes` | shapes filled at random (`cactusGlobe`, `tess_shape`, `flame_bulb`) |
//! | `jwf_h5_sims` | simulations (`truchet_ae`, `dla_wf`) |
//! | `jwf_h5_draw` | drawings of figures drawn once, one drawn at random per call (`curliecue`, `gpattern`, `triantruchet`) |
//! | `jwf_h5_crops` | crops and mirrors that remember points (`ringer`, `post_point_crop`, `point_mirror_symmetry`) |
//! | `jwf_h5_glsl` | a glowing-circuits shader stamp (`glsl_circuits`) |
//! | `jwf_h5_octree` | a flight through a random octree, as a stamp (`glsl_randomoctree`, `dc_randomoctree`) |
//! | `jwf_h5_triantess` | a triangle group's tessellation, as a stamp (`dc_triantess`) |
//! | `jwf_h9c_lsystem` | a Lindenmayer system drawn by a turtle, one segment per call (`lsystem_js`) |
//! | `jwf_h9c_subflame` | a flame run inside a variation (`subflame_wf`, `pre_subflame_wf`, `ringsubflame`, `glynns3subfl`) |
//! | `jwf_h9a_code` | Java-code variations, their default code (`custom_wf`, `custom_wf_full`, `pre_custom_wf`, `post_custom_wf`) |
//! | `jwf_h9a_fract` | escape-time sets of a complex formula (`fract_formula_julia_wf`, `fract_formula_mand_wf`) |
//! | `jwf_h9a_plots` | plots of formula text (`parplot2d_wf`, `polarplot2d_wf`, `yplot2d_wf`, `yplot3d_wf`, `isosfplot3d_wf`) |
//! | `jwf_h9b_images` | colour, displacement and bump maps with JWildfire's default images (`colormap_wf`, `displacemap_wf`, `post_bumpmap_wf`, …) |
//! | `jwf_h9b_meshes` | random points of a mesh, JWildfire's default cube or an OBJ file (`obj_mesh_wf`) |
//! | `jwf_pal_kaleido` | an image seen through 14 kaleidoscopes and warps (`kaleidoimg`) |
//! | `jwf_h9b_code` | a domain colouring of JWildfire's default complex function (`colordomain`) |
//! | `jwf_s10_maurer` | chords of nineteen curves in 25 render modes, filtered and coloured (`maurer_lines`; curves and modes in `jwf_s10_maurer_curves`, `jwf_s10_maurer_render`) |
//! | `jwf_s10_quad`, `jwf_s10_quad_subs` | the plane in four quadrants, each through a sub-variation of its own (`quad`) |
//! | `jwf_s10_tritile` | a random point of a random tile of a triangle substitution tiling (`dc_triTile`) |
//! | `jwf_s10_code` | Java-code escape-time pictures, their default code (`glsl_code`, `f_complex`, `ducks`) |
//! | `jwf_s10_code_dc` | a direct-colour stamp of a program written from a seed (`dc_code`) |
//! | `jwf_aa_svg` | the lit pixels of an SVG drawing (`svg_wf`; its reader in `jwf_aa_svgdoc`, the anti-aliased rasteriser in `jwf_aa_raster`) |
//! | `jwf_aa_truchet` | multi-scale Truchet tiles drawn into an image, looked up under the point (`msTruchet`) |
//! | `jwf_m_ifs3d` | the chaos game of 3-D cube fractals (`chaosCubes`) |
//! | `jwf_m_polylog` | the polylogarithm Li_n (`polylogarithm`) |
//! | `jwf_m_quaternion` | the quaternion functions summed (`quaternion`) |
//! | `jwf_m_stabilize` | restarts from fixed points (`pre_stabilize`) |
//! | `jwf_tp` | Craig S. Kaplan's Taprats star patterns drawn in one of its styles, one segment or triangle per call (`taprats`; planar maps in `jwf_tp_map`, figures in `jwf_tp_figures` and `jwf_tp_infer`, styles in `jwf_tp_render`, tilings in `jwf_tp_tiling`) |
//! | `jwf_m_tiles` | tilings drawn at random (`arctruchet`) |
//! | `jwf_m_trig` | sums of complex functions before or after the variations (`pre_recip`, `post_trig`) |
//! | `jwf_3d` | JWildfire's 3-D variations (`exblur`, `glitchy1`, `plane_wf`, `polarplot3d_wf`, `dla3d_wf`, …) |
//! | `jwf_dialect` | JWildfire's own formulas for names the others also use (`polar`, `rings`, …), for the flames JWildfire wrote |
//! | `jwf_direct_colour` | JWildfire's `dc_*` stamps and `julian2dc` |
//! | `jwf_drawings` | drawings, curves and filled figures (`hilbert_js`, `tree_js`, `rose_wf`, `nsudoku`, …) |
//! | `jwf_knots` | `knots3D` |
//! | `jwf_maps` | `complex`, `rosoni`, `svensson_js`, `crop_stars`, `post_mirror_wf` |
//! | `jwf_post_symmetry` | JWildfire's symmetries after the variations (`post_point_symmetry_wf`, `post_axis_symmetry_wf`) |
//! | `jwf_prepost` | JWildfire's own `pre_`/`post_` classes and its prepost variations (`pre_affine3D`, `post_crosscrop`, `prepost_mobius`, `ringtile`, …) |
//! | `jwf_symmetry` | the symmetry groups `sym_ng*` and `sym_bg*` |
//! | `jwf_text` | `text_wf` |
//! | `jwf_tx_iflames` | `iflames_wf` (its image part; the embedded flames are not built) |
//! | `jwf_br_brush` | strokes of JWildfire's brush images, per grid cell (`brush_stroke_wf`, `post_brush_stroke_wf`; image turning in `jwf_br_raster`) |
//! | `jwf_text_raster` | the image `text_wf` samples: a line of text in DejaVu Sans, drawn as Java 2D draws it |
//! | `jwf_z_3d` | JWildfire's 3-D curves and maps (`spirograph3D`, `mobiqN`, `hypertile3Db`, `juliascope3Db`, `checkerboard_wf`, …) |
//! | `jwf_z_solids` | JWildfire's 3-D figures (`mobius_dragon_3D`, `polySurf`, `primitives_wf`, `glynnSim2B`) |
//! | `jwf_z_warps` | JWildfire's warps by cells and shapes (`shape_warp`, `drunken_tiles`, `bwrands`, `de_stijl`, `glitchy2`) |
//! | `jwf_z_drawings` | Jesus Sosa's line drawings (`htree_js`, `koch_js`, `dragon_js`, `gosperisland_js`, `brownian_js`) |
//! | `jwf_z_flora` | `flora` (25 leaves and flowers) |
//! | `jwf_z_noise` | noise and shader patterns (`camouflage`, `truchetflow`, `kaplan`) |
//! | `jwf_z_plane` | JWildfire's plane maps and point sets (`jac_elk`, `jac_asn`, `pointgrid_wf`, `intersection`, `glynnspiro`, `juliascopePlus`) |
//! | `jwf_z_orbits` | orbits and curves of the plane (`gumowski_mira`, `starfractal`, `sphtiling3v2`, `iconattractor_js`, `harmonograph_js`) |
//! | `jwf_z_figures` | figures and mirrors (`meeple`, `tqmirror`, `rhodonea`) |
//! | `jwf_s10_geo_mesh` | JWildfire's built-in meshes built from their geometry (`obj_mesh_primitive_wf`) |
//! | `jwf_s10_geo_attractor` | a tube around a strange attractor's orbit, as a mesh (`sattractor3D`) |
//! | `jwf_sv_sunvoroni` | a sunflower's Voronoi diagram, cells filled and edges drawn (`sunvoroni`; its convex hull by QuickHull3D in `jwf_sv_quickhull`) |
//! | `jwf_ls_mesh` | a 3-D L-system (Lapre's LParser) drawn as a mesh, random points of it (`lsystem3D_js`; grammar, turtle and presets in `jwf_ls_grammar`, `jwf_ls_turtle`, `jwf_ls_presets`) |

pub use crate::flame::affine::Affine;

mod batch;
mod def;
mod names;
mod palette_index;
mod params;
mod point;
mod prepare;
mod registry;

mod flam3;
mod fr_3d;
mod fr_bipolar_elliptic;
mod fr_blurs;
mod fr_complex;
mod fr_crops;
mod fr_curves;
mod fr_direct_colour;
mod fr_distance_blurs;
mod fr_grids;
mod fr_hexagons;
mod fr_hyperbolic;
mod fr_inversions;
mod fr_julias;
mod fr_moves;
mod fr_polynomial_maps;
mod fr_quaternions;
mod fr_radial;
mod fr_synth;
mod fr_trig;
mod fr_truchet;
mod fr_waves;
// JWildfire variations, first set of files.
mod jwf_3d;
// JWildfire variations, second part.
mod jwf_a_complex;
mod jwf_a_crops;
mod jwf_a_cuts;
mod jwf_a_dc;
mod jwf_a_fractals;
mod jwf_a_ifs;
mod jwf_a_plane;
mod jwf_a_sdf3d;
mod jwf_a_shapes;
mod jwf_a_surfaces;
mod jwf_a_warps;
mod jwf_aa_raster;
mod jwf_aa_svg;
mod jwf_aa_svgdoc;
mod jwf_aa_svgpath;
mod jwf_aa_truchet;
mod jwf_b_3d;
mod jwf_b_complex;
mod jwf_b_crops;
mod jwf_b_cuts;
mod jwf_b_dc;
mod jwf_b_ifs;
mod jwf_b_shapes;
mod jwf_br_brush;
mod jwf_br_raster;
mod jwf_c_escape;
mod jwf_c_glsl;
mod jwf_c_orbits;
mod jwf_d_crops;
mod jwf_d_cuts;
mod jwf_d_cvar;
mod jwf_d_plane;
mod jwf_d_solids;
mod jwf_dc_cells;
mod jwf_dc_fields;
mod jwf_dc_folds;
mod jwf_dc_mandel;
mod jwf_dc_maps;
mod jwf_dc_maths;
mod jwf_dc_patterns;
mod jwf_dc_tiles;
mod jwf_dc_twins;
mod jwf_dialect;
mod jwf_direct_colour;
mod jwf_drawings;
mod jwf_h4_cells;
mod jwf_h4_hamid;
mod jwf_h4_ifs;
mod jwf_h4_inversion;
mod jwf_h4_kifs;
mod jwf_h4_klein;
mod jwf_h4_mandala;
mod jwf_h4_metaballs;
mod jwf_h4_recurrence;
mod jwf_h4_shapes;
mod jwf_h4_terrain;
mod jwf_h5_crops;
mod jwf_h5_draw;
mod jwf_h5_glsl;
mod jwf_h5_octree;
mod jwf_h5_shapes;
mod jwf_h5_sims;
mod jwf_h5_triantess;
mod jwf_h9a_code;
mod jwf_h9a_fract;
mod jwf_h9a_plots;
mod jwf_h9b_code;
mod jwf_h9b_images;
mod jwf_h9b_meshes;
mod jwf_h9c_lsystem;
mod jwf_h9c_subflame;
mod jwf_knots;
mod jwf_ls_grammar;
mod jwf_ls_mesh;
mod jwf_ls_presets;
mod jwf_ls_turtle;
mod jwf_m_crops;
mod jwf_m_curves;
mod jwf_m_cuts;
mod jwf_m_draw;
mod jwf_m_foam;
mod jwf_m_ifs3d;
mod jwf_m_polylog;
mod jwf_m_quaternion;
mod jwf_m_stabilize;
mod jwf_m_tilecuts;
mod jwf_m_tiles;
mod jwf_m_trig;
mod jwf_maps;
mod jwf_pal_kaleido;
mod jwf_post_symmetry;
mod jwf_prepost;
mod jwf_s10_code;
mod jwf_s10_code_dc;
mod jwf_s10_geo_attractor;
mod jwf_s10_geo_mesh;
mod jwf_s10_maurer;
mod jwf_s10_maurer_curves;
mod jwf_s10_maurer_render;
mod jwf_s10_quad;
mod jwf_s10_quad_subs;
#[cfg(test)]
mod jwf_s10_quad_tests;
mod jwf_s10_tritile;
mod jwf_sv_quickhull;
mod jwf_sv_sunvoroni;
mod jwf_symmetry;
#[cfg(test)]
mod jwf_testing;
mod jwf_text;
mod jwf_text_raster;
mod jwf_tp;
mod jwf_tp_figures;
mod jwf_tp_infer;
mod jwf_tp_map;
mod jwf_tp_render;
mod jwf_tp_tiling;
mod jwf_tx_iflames;
mod jwf_wt_tiling;
mod jwf_wt_wangtiles;
// JWildfire variations, from the end of the alphabet.
mod jwf_z_3d;
mod jwf_z_drawings;
mod jwf_z_figures;
mod jwf_z_flora;
mod jwf_z_noise;
mod jwf_z_orbits;
mod jwf_z_plane;
mod jwf_z_solids;
mod jwf_z_warps;
mod noise;
pub mod resources;
mod shared;
pub(crate) mod util;

pub use crate::flame::fastmath::Simd;
pub use batch::time_batches;
pub(crate) use batch::{DrawnFormula, Row, batch_with_draws};
pub(crate) use batch::{batch_with, generic_batch};
pub(crate) use batch::{inline_batch, inline_batch_drawn, inlined, inlined_drawn};
pub use def::{
    Assign, BatchFn, Dialect, EvalFn, Form, FormBatchFn, PrepareFn, Prepared, Rules, VarDef,
    VarState, ZRule, flag,
};
pub(crate) use flam3::Draws;
pub use flam3::*;
pub use jwf_br_brush::{BRUSH_PREFIX, brush_name, brush_resources};
pub use jwf_dc_folds::{
    dc_fractcolor_xpar_of_seed, dc_fractcolor_ypar_of_seed, dc_warping_x0_of_seed,
};
pub use jwf_z_orbits::gumowski_mira_rendered;
pub use names::{
    apophysis_param_of, attr_name, by_name, from_flam3_index, is_foreign_variation_name,
    param_attr_name, param_attr_name_in, param_of, parse_name, text_attr_name, text_of,
    text_problem,
};
pub use palette_index::PaletteIndex;
pub use params::{
    Param, ParamKind, TextParam, p, p_cyclic, p_int, p_int_nonzero, p_nonzero, p_range,
};
pub use point::{Acc, VarIn, need, own_rgb};
pub(crate) use point::{SoaAcc, SoaIn};
pub use prepare::{eval_point, eval_prepared};
pub use registry::{
    all, count, def_in, info, jwildfire_runs_after, jwildfire_twin, param_defaults,
};
pub use shared::{BuildFn, SharedDef};

// For the formulas' files, which import everything above with `use super::*`.
use crate::flame::rng::FastRng;
use def::sum_or_input;
use params::{INF, NEG_INF, params_of};

/// flam3's `EPS`, the guard its formulas add to denominators.
pub const EPS: f64 = 1e-10;

/// Index of a variation in the registry ([`all`]). Ids 0–98 are flam3's list, in flam3's order.
pub type VarId = u16;

/// An output point `[x, y, z]`.
pub type V3 = [f64; 3];
