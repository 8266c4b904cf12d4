//! A flame run inside a variation, as JWildfire's sub-flame variations run one (JWildfire
//! 9.00, `SubFlameWFFunc`; LGPL-2.1, the behaviour written anew): a small chaos game whose
//! point moves one step per call, the variation returning the step's point.
//!
//! The engine does not read flame files: a sub-flame reaches it as a *description*, a text of
//! one line per xform that the reader fills from the flame a file embeds (and that holds, by
//! default, the flame JWildfire embeds). Each line is blank-separated `key=value` words:
//!
//! ```text
//! xform weight=0.5 color=0 symmetry=-1 coefs=1,0,0,1,0,0 post=1,0,0,1,0,0 chaos=1,1 opacity=1 linear3D=1
//! finalxform color=0 symmetry=1 coefs=… spherical=0.5
//! palette=D45334CF5635…
//! preserve_z=0
//! ```
//!
//! `coefs`/`post` are flam3's six coefficients `a b c d e f`, `symmetry` JWildfire's colour
//! symmetry (the colour speed is (1 − symmetry)/2), a word naming a variation gives its weight
//! and a word naming a parameter its value (the names a flame file uses). `palette` holds the
//! hex colours (six digits each) the point's colour looks up when a caller asks for its red,
//! green or blue. Unknown words are skipped; the sizes are bounded ([`MAX_XFORMS`],
//! [`MAX_VARS`], [`MAX_TEXT`]).

use std::cell::RefCell;
use std::f64::consts::PI;
use std::rc::Rc;

use super::util::Mwc;
use super::*;
use crate::flame::affine::Affine;

/// Most xforms (and, separately, final xforms) a description may have; more are ignored.
pub const MAX_XFORMS: usize = 64;
/// Most variations an xform of a description may have; more are ignored.
pub const MAX_VARS: usize = 16;
/// Most bytes of a description.
pub const MAX_TEXT: usize = 1 << 20;
/// Steps JWildfire makes before the first point it returns (`prefuseIter`).
const PREFUSE: usize = 42;
/// Most steps one call makes looking for an xform whose point is drawn (JWildfire's
/// `MAX_ITER`).
const MAX_STEPS: usize = 1000;
/// Size of an xform's table of next xforms (JWildfire's `NEXT_APPLIED_XFORM_TABLE_SIZE`).
const TABLE: usize = 1024;

/// One xform of a sub-flame, its variations prepared as JWildfire runs them.
struct SubXform {
    coefs: Affine,
    post: Option<Affine>,
    pre: Vec<Prepared>,
    vars: Vec<Prepared>,
    posts: Vec<Prepared>,
    needs: u8,
    color: f64,
    speed: f64,
    opacity: f64,
}

/// A sub-flame ready to iterate.
pub(super) struct SubFlame {
    xforms: Vec<SubXform>,
    finals: Vec<SubXform>,
    /// For each xform, the xform applied after it, by a draw of [0, [`TABLE`]) (empty: none).
    next: Vec<Vec<u16>>,
    /// Palette entries as JWildfire's renderer holds them (0–255 scaled by 200/256).
    palette: Vec<[f64; 3]>,
}

/// A point of the sub-flame's chaos game.
#[derive(Clone, Copy, Debug, Default)]
pub(super) struct SubPt {
    pub x: f64,
    pub y: f64,
    pub z: f64,
    pub color: f64,
    /// Red, green, blue (0–255 scaled as JWildfire's renderer scales them): the palette's
    /// at the colour, or those a direct-colour variation set.
    pub rgb: [f64; 3],
    /// A direct-colour variation set `rgb`.
    pub own: bool,
    pub hide: bool,
}

/// One parsed xform line: the model xform, its chaos row and colour symmetry.
struct Line {
    xf: SubLine,
    fin: bool,
}

struct SubLine {
    weight: f64,
    color: f64,
    symmetry: f64,
    opacity: f64,
    coefs: [f64; 6],
    post: [f64; 6],
    chaos: Vec<f64>,
    /// (variation, form, weight, parameters).
    vars: Vec<(VarId, Form, f64, Vec<f64>)>,
}

fn numbers(v: &str, n: usize) -> Vec<f64> {
    v.split(',')
        .take(n)
        .map(|s| s.trim().parse::<f64>().unwrap_or(f64::NAN))
        .collect()
}

fn six(v: &str, dflt: [f64; 6]) -> [f64; 6] {
    let n = numbers(v, 6);
    if n.len() == 6 && n.iter().all(|x| x.is_finite()) {
        [n[0], n[1], n[2], n[3], n[4], n[5]]
    } else {
        dflt
    }
}

const IDENTITY: [f64; 6] = [1.0, 0.0, 0.0, 1.0, 0.0, 0.0];

fn parse_line(words: &[&str], fin: bool) -> Line {
    let mut l = SubLine {
        weight: if fin { 0.0 } else { 0.5 },
        color: 0.0,
        symmetry: if fin { 1.0 } else { 0.0 },
        opacity: 1.0,
        coefs: IDENTITY,
        post: IDENTITY,
        chaos: Vec::new(),
        vars: Vec::new(),
    };
    let mut params: Vec<(VarId, Form, usize, f64)> = Vec::new();
    for w in words {
        let Some((k, v)) = w.split_once('=') else {
            continue;
        };
        let num = || v.trim().parse::<f64>().ok().filter(|x| x.is_finite());
        match k {
            "weight" => l.weight = num().map_or(l.weight, |x| x.max(0.0)),
            "color" => l.color = num().unwrap_or(0.0),
            "symmetry" => l.symmetry = num().unwrap_or(0.0),
            "opacity" => l.opacity = num().unwrap_or(1.0),
            "coefs" => l.coefs = six(v, IDENTITY),
            "post" => l.post = six(v, IDENTITY),
            "chaos" => {
                l.chaos = numbers(v, MAX_XFORMS)
                    .into_iter()
                    .map(|x| if x.is_finite() { x.max(0.0) } else { 1.0 })
                    .collect()
            }
            _ => {
                if let Some((id, form)) = parse_name(k) {
                    if l.vars.len() < MAX_VARS
                        && let Some(w) = num()
                    {
                        l.vars.push((id, form, w, param_defaults(id)));
                    }
                } else if let Some((id, form, i)) = param_of(k)
                    && let Some(x) = num()
                {
                    params.push((id, form, i, x));
                }
            }
        }
    }
    for (id, form, i, x) in params {
        if let Some(var) = l.vars.iter_mut().find(|v| v.0 == id && v.1 == form)
            && let Some(slot) = var.3.get_mut(i)
        {
            *slot = x;
        }
    }
    Line { xf: l, fin }
}

/// JWildfire's rules for the variations of a sub-flame.
fn rules(preserve_z: bool) -> Rules {
    Rules {
        compat: true,
        dialect: Dialect::JWildfire,
        preserve_z,
    }
}

fn compile(l: &SubLine, preserve_z: bool) -> SubXform {
    let coefs = Affine::from_coefs(l.coefs);
    let post = Affine::from_coefs(l.post);
    let mut x = SubXform {
        coefs,
        post: (!post.is_identity()).then_some(post),
        pre: Vec::new(),
        vars: Vec::new(),
        posts: Vec::new(),
        needs: 0,
        color: l.color,
        speed: (1.0 - l.symmetry) / 2.0,
        opacity: l.opacity,
    };
    for (id, form, w, params) in &l.vars {
        let prep = |form| Prepared::for_flame(*id, form, *w, params, &[], coefs, rules(preserve_z));
        let p = prep(*form);
        if p.def.has(flag::PREPOST) {
            x.pre.push(prep(Form::Pre));
            x.posts.push(prep(Form::Post));
            continue;
        }
        match p.form {
            Form::Pre => x.pre.push(p),
            Form::Regular => {
                x.needs |= p.def.needs;
                x.vars.push(p);
            }
            Form::Post => x.posts.push(p),
        }
    }
    x
}

/// JWildfire's table of next xforms for xform `k` (`Layer.refreshModWeightTables`): entry i
/// is the first xform whose running sum of weight·chaos exceeds i/1024 of the total.
fn next_table(lines: &[&SubLine], k: usize) -> Vec<u16> {
    let chaos = |j: usize| lines[k].chaos.get(j).copied().unwrap_or(1.0);
    let tp: Vec<f64> = (0..lines.len())
        .map(|j| lines[j].weight * chaos(j))
        .collect();
    let total: f64 = tp.iter().sum();
    if !(total > 0.0 && total.is_finite()) {
        return Vec::new();
    }
    let n = lines.len();
    let mut table = Vec::with_capacity(TABLE);
    let mut at = 0.0;
    for _ in 0..TABLE {
        let mut sum = 0.0;
        let mut j = 0;
        loop {
            sum += tp[j];
            if sum > at || j == n - 1 {
                break;
            }
            j += 1;
        }
        table.push(j as u16);
        at += total / TABLE as f64;
    }
    table
}

fn hex_palette(v: &str) -> Vec<[f64; 3]> {
    let b = v.as_bytes();
    let digit = |c: u8| (c as char).to_digit(16).map(f64::from);
    b.chunks_exact(6)
        .take(256)
        .map_while(|c| {
            let mut rgb = [0.0; 3];
            for (k, ch) in rgb.iter_mut().enumerate() {
                *ch = (digit(c[2 * k])? * 16.0 + digit(c[2 * k + 1])?) * 200.0 / 256.0;
            }
            Some(rgb)
        })
        .collect()
}

/// Reads a description (see the module's text); `None` when it has no xform.
pub(super) fn parse(text: &str) -> Option<SubFlame> {
    let text = &text[..text.len().min(MAX_TEXT)];
    let mut lines = Vec::new();
    let mut palette = Vec::new();
    let mut preserve_z = false;
    for line in text.lines() {
        let words: Vec<&str> = line.split_whitespace().collect();
        match words.first() {
            Some(&"xform") => lines.push(parse_line(&words[1..], false)),
            Some(&"finalxform") => lines.push(parse_line(&words[1..], true)),
            Some(w) if w.starts_with("palette=") => palette = hex_palette(&w[8..]),
            Some(w) if w.starts_with("preserve_z=") => preserve_z = w[11..].trim() == "1",
            _ => {}
        }
    }
    let xf: Vec<&SubLine> = lines
        .iter()
        .filter(|l| !l.fin)
        .map(|l| &l.xf)
        .take(MAX_XFORMS)
        .collect();
    if xf.is_empty() {
        return None;
    }
    let fins = lines.iter().filter(|l| l.fin).take(MAX_XFORMS);
    Some(SubFlame {
        next: (0..xf.len()).map(|k| next_table(&xf, k)).collect(),
        xforms: xf.iter().map(|l| compile(l, preserve_z)).collect(),
        finals: fins.map(|l| compile(&l.xf, preserve_z)).collect(),
        palette,
    })
}

thread_local! {
    /// The sub-flames this thread has compiled, by description (a few, most recent last).
    static COMPILED: RefCell<Vec<(String, Option<Rc<SubFlame>>)>> = const { RefCell::new(Vec::new()) };
}

/// The compiled sub-flame of a description (compiled once per thread).
pub(super) fn compiled(text: &str) -> Option<Rc<SubFlame>> {
    let found = COMPILED.with(|c| {
        let c = c.borrow();
        c.iter().find(|(t, _)| t == text).map(|(_, s)| s.clone())
    });
    if let Some(s) = found {
        return s;
    }
    // Compiled outside the borrow: compiling may prepare a sub-flame variation in turn.
    let s = parse(text).map(Rc::new);
    COMPILED.with(|c| {
        let mut c = c.borrow_mut();
        if c.len() >= 8 {
            c.remove(0);
        }
        c.push((text.to_string(), s.clone()));
    });
    s
}

impl SubXform {
    /// JWildfire's `XForm.transformPoint` with colour type DIFFUSION: affine map, `pre_`
    /// variations, the sum of the regular ones, `post_` ones, post-affine map, palette colour.
    fn apply(&self, p: &SubPt, palette: &[[f64; 3]], rng: &mut FastRng) -> SubPt {
        let blended = self.speed * self.color + (1.0 - self.speed) * p.color;
        let (tx, ty) = self.coefs.apply(p.x, p.y);
        let mut acc = Acc {
            color: blended,
            ..Acc::default()
        };
        let mut tr = [tx, ty, p.z];
        for v in &self.pre {
            v.apply_pre(&mut tr, &mut acc, blended, rng);
        }
        (acc.x, acc.y, acc.z) = (0.0, 0.0, 0.0);
        if !self.vars.is_empty() {
            let t = VarIn::new(tr[0], tr[1], tr[2], acc.color, self.needs, false);
            for v in &self.vars {
                let o = v.eval(&t, &mut acc, rng);
                acc.x += o[0];
                acc.y += o[1];
                acc.z += o[2];
            }
        }
        let c = acc.color;
        for v in &self.posts {
            v.apply_post_after(&tr, &mut acc, c, rng);
        }
        if let Some(post) = &self.post {
            (acc.x, acc.y) = post.apply(acc.x, acc.y);
        }
        let rgb = acc.rgb.unwrap_or_else(|| {
            // JWildfire's gradient colour step: entry (int)(colour·(256 − 2) + ½).
            let i = (acc.color * 254.0 + 0.5).clamp(0.0, 255.0) as usize;
            palette.get(i).copied().unwrap_or([0.0; 3])
        });
        SubPt {
            x: acc.x,
            y: acc.y,
            z: acc.z,
            color: acc.color,
            rgb,
            own: acc.rgb.is_some(),
            hide: acc.hide,
        }
    }
}

/// State slots of a sub-flame variation: started, the point (x, y, z, colour), the xform.
const ST_STARTED: usize = 0;
const ST_X: usize = 1;
const ST_XFORM: usize = 5;

fn load(v: &Prepared) -> (SubPt, usize) {
    let p = SubPt {
        x: v.state.get(ST_X),
        y: v.state.get(ST_X + 1),
        z: v.state.get(ST_X + 2),
        color: v.state.get(ST_X + 3),
        ..SubPt::default()
    };
    (p, v.state.get(ST_XFORM) as usize)
}

fn store(v: &Prepared, p: &SubPt, k: usize) {
    v.state.set(ST_STARTED, 1.0);
    v.state.set(ST_X, p.x);
    v.state.set(ST_X + 1, p.y);
    v.state.set(ST_X + 2, p.z);
    v.state.set(ST_X + 3, p.color);
    v.state.set(ST_XFORM, k as f64);
}

impl SubFlame {
    /// The xform after xform `k` (`None`: its weights are all 0).
    fn step_from(&self, k: usize, u: f64) -> Option<usize> {
        let t = self.next.get(k)?;
        let i = (u * TABLE as f64) as usize;
        t.get(i.min(TABLE - 1)).map(|&j| j as usize)
    }

    /// A fresh start (`prefuseIter`): a random point, 42 steps from the first xform, the
    /// point and the xforms drawn by `u` (the variations draw from `rng`).
    fn prefuse(&self, mut u: impl FnMut() -> f64, rng: &mut FastRng) -> (SubPt, usize) {
        let mut p = SubPt {
            x: u() - 0.5,
            y: u() - 0.5,
            z: 0.0,
            color: u(),
            ..SubPt::default()
        };
        let mut k = 0;
        for _ in 0..PREFUSE {
            let Some(j) = self.step_from(k, u()) else {
                break;
            };
            k = j;
            p = self.xforms[k].apply(&p, &self.palette, rng);
        }
        (p, k)
    }

    /// One call's point (`subflameIter` before its scaling): steps until an xform whose
    /// point is drawn, then the final xforms. `None` when no such xform was reached.
    pub(super) fn next_point(&self, v: &Prepared, rng: &mut FastRng) -> Option<SubPt> {
        let (mut p, mut k) = load(v);
        let bad = !(p.x.is_finite() && p.y.is_finite() && p.z.is_finite());
        if v.state.get(ST_STARTED) == 0.0 {
            // JWildfire makes the first start in `init`, before the render draws any point,
            // from its generator (Marsaglia's) as seeded then: a fixed start, the same for
            // every use of the same sub-flame.
            let mut init = Mwc::new(1);
            (p, k) = self.prefuse(|| init.next_f64(), rng);
        } else if bad || k >= self.xforms.len() {
            let mut vars_rng = FastRng::new(rng.u64());
            (p, k) = self.prefuse(|| rng.f01(), &mut vars_rng);
        }
        let mut out = None;
        for _ in 0..MAX_STEPS {
            let Some(j) = self.step_from(k, rng.f01()) else {
                break;
            };
            k = j;
            let xf = &self.xforms[k];
            p = xf.apply(&p, &self.palette, rng);
            if xf.opacity <= 0.0 || (xf.opacity < 1.0 && rng.f01() > xf.opacity) {
                continue;
            }
            let mut q = p;
            for f in &self.finals {
                q = f.apply(&q, &self.palette, rng);
            }
            out = Some(q);
            break;
        }
        store(v, &p, k);
        out
    }
}

/// The parameters every sub-flame variation has, in JWildfire's order, after its own.
macro_rules! subflame_params {
    ($n:literal) => {
        subflame_params!($n, -1.0)
    };
    ($n:literal, $color_mode:literal) => {
        [
            p(concat!($n, "_scale"), 1.0),
            p(concat!($n, "_angle"), 0.0),
            p(concat!($n, "_offset_x"), 0.0),
            p(concat!($n, "_offset_y"), 0.0),
            p(concat!($n, "_offset_z"), 0.0),
            p(concat!($n, "_colorscale_z"), 0.0),
            p_int(concat!($n, "_color_mode"), $color_mode, -2.0, 4.0),
            p_int(concat!($n, "_flame_is_sequence"), 0.0, 0.0, 2.0),
            p_int(
                concat!($n, "_flame_sequence_start"),
                1.0,
                -2147483648.0,
                2147483647.0,
            ),
            p_int(
                concat!($n, "_flame_sequence_end"),
                0.0,
                -2147483648.0,
                2147483647.0,
            ),
            p_int(
                concat!($n, "_flame_sequence_repeat"),
                1.0,
                -2147483648.0,
                2147483647.0,
            ),
            p_int(
                concat!($n, "_flame_sequence_digits"),
                4.0,
                -2147483648.0,
                2147483647.0,
            ),
        ]
    };
}

/// JWildfire's colour modes (`color_mode`).
const CM_FLAME: f64 = -2.0;
const CM_OFF: f64 = -1.0;
const CM_DIRECT: f64 = 0.0;

/// A sub-flame variation's point for this call, scaled, turned and moved by its parameters
/// (from `base` on in `v.p`: scale, angle, offsets, colorscale_z), and its colour written to
/// `acc` as `color_mode` asks. `None` when the sub-flame is empty or drew nothing.
pub(super) fn sub_point(
    v: &Prepared,
    base: usize,
    acc: &mut Acc,
    rng: &mut FastRng,
) -> Option<SubPt> {
    let flame = compiled(v.texts.first().map_or("", |t| t.as_str()))?;
    let q = flame.next_point(v, rng)?;
    let [scale, angle, ox, oy, oz, cz, mode] =
        std::array::from_fn(|i| v.p.get(base + i).copied().unwrap_or(0.0));
    let (s, c) = (angle * PI / 180.0).sin_cos();
    let (x, y) = (scale * q.x, scale * q.y);
    let out = SubPt {
        x: x * c - y * s + ox,
        y: x * s + y * c + oy,
        z: scale * q.z + oz + cz * q.color,
        ..q
    };
    set_color(&q, mode, acc);
    Some(out)
}

/// JWildfire's `setColor`: hide with the sub-flame's point, else colour it as `mode` says.
fn set_color(q: &SubPt, mode: f64, acc: &mut Acc) {
    if q.hide {
        acc.hide = true;
        return;
    }
    acc.hide = false;
    if mode == CM_OFF {
        return;
    }
    let rgb = q.rgb;
    if q.own || mode == CM_FLAME {
        acc.rgb = Some(rgb);
        acc.color = q.color;
    }
    acc.color = match mode {
        CM_DIRECT | CM_FLAME => q.color,
        1.0 => rgb[0] / 255.0,
        2.0 => rgb[1] / 255.0,
        3.0 => rgb[2] / 255.0,
        _ => (0.2990 * rgb[0] + 0.5880 * rgb[1] + 0.1130 * rgb[2]) / 255.0,
    };
}

/// JWildfire's default sub-flame (`SubFlameWFFunc.DFLT_FLAME_XML`): a waves2_wf and popcorn2
/// spiral with a spherical3D and a linear3D xform.
pub const DEFAULT_FLAME: &str = concat!(
    "xform weight=37.974195875650885 color=0 symmetry=0.6363142683575415",
    " coefs=0.29869999951569876,0.9193040710637221,-0.9193040710637221,0.29869999951569876,-1.6842788839099072,2.0224216083110305",
    " chaos=1,1,1 waves2_wf=1 waves2_wf_scalex=0.05411632642405888",
    " waves2_wf_scaley=0.07140430473672771 waves2_wf_freqx=5.665411884739101",
    " waves2_wf_freqy=3.5622214535317194 waves2_wf_use_cos_x=0 waves2_wf_use_cos_y=0",
    " waves2_wf_dampx=0 waves2_wf_dampy=-0.0749313500620006 popcorn2=1.1747945422649702E-4",
    " popcorn2_x=1 popcorn2_y=0.5 popcorn2_c=1.5\n",
    "xform weight=0.5 color=0 symmetry=-1 coefs=1,0,0,1,0,0 chaos=1,1,1",
    " spherical3D=0.43660175471191676\n",
    "xform weight=0.5 color=0 symmetry=-1",
    " coefs=0.9321767990927353,-0.36200333594211836,0.36200333594211836,0.9321767990927353,-0.1636856703682093,0.5528632251910492",
    " chaos=1,1,1 linear3D=1\n",
    "palette=",
    "D45334CF5635CA5936C55C38C05F39BC623AB7653BB2683DAD6B3EA86E3FA371409E7442997743947A44",
    "8F7D458B80478683488186497C894A778C4C728F4D6D924E68944F6397515E9A525A9D5355A05450A356",
    "4BA65746A95841AC593CAF5B37B25C32B55D2DB85E29BB5F24BE611FC1621AC46315C76410CA660BCD67",
    "06D06804D26A07D16C0AD06E0DCF710FCE7312CD7615CC7818CB7A1BCA7D1EC97F21C88124C78427C686",
    "29C5882CC48B2FC38D32C28F35C19238C0943BBF963EBE9941BE9B43BD9D46BCA049BBA24CBAA44FB9A7",
    "52B8A955B7AB58B6AE5AB5B05DB4B260B3B563B2B766B1B969B0BC6CAFBE6FAEC172ADC374ACC577ABC8",
    "7AAACA7DA9CC80A9CD82A9CD85A8CD87A8CD8AA8CD8DA7CD8FA7CD92A7CD94A7CD97A6CD9AA6CD9CA6CD",
    "9FA5CDA1A5CDA4A5CDA6A5CDA9A4CDACA4CDAEA4CDB1A3CDB3A3CDB6A3CCB8A3CCBBA2CCBEA2CCC0A2CC",
    "C3A2CCC5A1CCC8A1CCCAA1CCCDA0CCD0A0CCD2A0CCD5A0CCD79FCCDA9FCCDD9FCCDF9ECCE29ECCE49ECC",
    "E79ECCE99DCCEC9DCCEA9BC8E798C4E596C0E394BCE091B7DE8FB3DB8DAFD98AABD788A7D486A3D2839F",
    "D0819BCD7F97CB7C93C87A8EC6788AC47586C17382BF707EBD6E7ABA6C76B86972B6676EB3656AB16265",
    "AE6061AC5E5DAA5B59A75955A55751A3544DA052499E50459C4D41994B3C97493894463492443090422C",
    "8D3F288B3D24893B2087391E89381F8A37218B36238D35258E34268F332891322A92312B93302D952F2F",
    "962E31972D32992D349A2C369B2B389C2A399E293B9F283DA0273FA22640A32542A42444A62345A72247",
    "A82149AA204BAB1F4CAC1E4EAE1E50AF1D52B01C53B11B55B31A57B41959B5185AB7175CB8165EB9155F",
    "BB1461BC1363BD1265BF1166BE1166BC1066BA1065B71064B50F63B30F63B10F62AF0E61AD0E60AB0E60",
    "A90E5FA70D5EA50D5DA30D5CA10C5C9F0C5B9D0C5A9B0B59990B59960B58940A57920A56900A558E0955",
    "8C09548A095388085286085284085182075080074F7E074F7C064E7A064D78064C75054B73054B71054A",
    "6F04496D04486B0448690347",
    "\n",
);

/// ringsubflame's default sub-flame (`RingSubFlameFunc.NEW_DFLT_FLAME_XML`): a clifford_js
/// attractor, with a dc_hexes_wf at weight 0 that colours it.
pub const RING_FLAME: &str = concat!(
    "xform weight=0.5 color=0 symmetry=0 coefs=1,0,0,1,0,0 chaos=1",
    " clifford_js=1 clifford_js_a=-1.7080000000000002 clifford_js_b=2.12 clifford_js_c=0.988",
    " clifford_js_d=1.468 dc_hexes_wf=0 dc_hexes_wf_cellsize=0.45999999999999996",
    " dc_hexes_wf_power=1 dc_hexes_wf_rotate=0.166 dc_hexes_wf_scale=1",
    " dc_hexes_wf_color_scale=0.5 dc_hexes_wf_color_offset=0\n",
    "palette=",
    "F54F16ED4C18E5491ADD461DD4431FCC4021C43D23BC3A26B43728AC342AA3312C9B2E2E932B318B2833",
    "8325357B223772203A6A1D3C621A3E5A17405214434A1145410E47390B4931084B29054E25074F27104F",
    "291A4F2B244F2D2D502F3750314050334A50355350375D503967503B70503D7A503F8351418D51439651",
    "45A05147AA5149B3514BBD514DC6514FD05251D95253E35255ED5257F65259F2505AEB4D5CE44A5EDD47",
    "60D64462CF4164C83E66C13B68BA386AB3356CAC326EA52F709E2C719729739026758923778220797B1D",
    "7B741A7D6D177F6614815F1183580E85510B864A08884406884106893F06893D06893B068939068A3606",
    "8A34068A32068B30068B2E068B2C068B29068C27068C25068C23068C21068D1E068D1C068D1A068E1806",
    "8E16068E13068E11068F0F068F0D068E0F068C13068A1706871C068520068325068129067F2E067D3206",
    "7B3606793B06773F06744406724805704C056E51056C55056A5A05685E05666305646705616B055F7005",
    "5D74055B7905597D055B79055D76055F7205616F05646B056668056864056A61056C5D056E5A05705605",
    "725305744F06774C067948067B45067D41067F3E06813A068337068533068730068A2C068C29068E2506",
    "8D23068924068524068025057C25057826057426056F26056B27056727056228045E28045A2904552904",
    "512A044D2A04492B03442B03402C033C2C03372D03332D032F2E032A2E02262E02222F022535032B3D04",
    "304505354D063B5407405C0945640A4B6C0B50730C557B0D5B830E608B0F6693116B9A1270A21376AA14",
    "7BB21580B91686C1178BC91890D11A96D81B9BE01CA0E81DA6F01EAAF620ACF623AEF626AFF629B1F62B",
    "B3F72EB4F731B6F734B8F737B9F73ABBF73DBDF740BEF743C0F846C2F849C4F84CC5F84FC7F852C9F855",
    "CAF858CCF85BCEF85ECFF961D1F964D3F967D4F96AD6F76ED7F474D9F179DAEE7FDCEB85DDE88ADFE490",
    "E0E195E2DE9BE3DBA0E5D8A6E6D5ABE8D2B1E9CFB6EBCBBCECC8C2EEC5C7EFC2CDF1BFD2F2BCD8F4B9DD",
    "F5B6E3F7B2E8F8AFEEFAACF3",
    "\n",
);

pub(super) static DEFS: &[VarDef] = &[
    VarDef::new("subflame_wf", subflame_wf)
        .params(&subflame_params!("subflame_wf"))
        .texts(&[TextParam {
            name: "subflame_wf_flame_model",
            default: DEFAULT_FLAME,
            max_len: MAX_TEXT,
        }])
        .flags(SUBFLAME),
    VarDef::new("pre_subflame_wf", pre_subflame_wf)
        .params(&subflame_params!("pre_subflame_wf"))
        .texts(&[TextParam {
            name: "pre_subflame_wf_flame_model",
            default: DEFAULT_FLAME,
            max_len: MAX_TEXT,
        }])
        .flags(SUBFLAME | flag::PRE_ONLY),
    VarDef::new("ringsubflame", ringsubflame)
        .params(&RING_PARAMS)
        .texts(&[TextParam {
            name: "ringsubflame_flame_model",
            default: RING_FLAME,
            max_len: MAX_TEXT,
        }])
        .flags(SUBFLAME | flag::READS_ACC | flag::WRITES_ACC),
    VarDef::new("glynns3subfl", glynns3subfl)
        .params(&GLYNN_PARAMS)
        .texts(&[TextParam {
            name: "glynns3subfl_flame_model",
            default: DEFAULT_FLAME,
            max_len: MAX_TEXT,
        }])
        .flags(SUBFLAME | flag::WRITES_ACC),
];

/// ringsubflame's parameters, then the sub-flame's.
const RING_PARAMS: [Param; 20] = {
    let own = [
        p_int("ringsubflame_hide_inner", 0.0, 0.0, 1.0),
        p("ringsubflame_innerradius", 0.5),
        p("ringsubflame_outerradius", 1.0),
        p_range("ringsubflame_thickness", 0.0, 0.0, 1.0),
        p_range("ringsubflame_contrast", 0.0, 0.0, 1.0),
        p("ringsubflame_pow", 1.0),
        p("ringsubflame_scatter_area", 0.0),
        p_int("ringsubflame_hide_outer", 1.0, 0.0, 1.0),
    ];
    join::<8, 12, 20>(own, subflame_params!("ringsubflame"))
};

/// glynns3subfl's parameters, then the sub-flame's (colour mode 0: the sub-flame's colour).
const GLYNN_PARAMS: [Param; 21] = {
    let own = [
        p_range("glynns3subfl_weight", 0.5, 0.0, 1.0),
        p_int("glynns3subfl_show/hide(1/0)", 1.0, 0.0, 1.0),
        p("glynns3subfl_radius", 1.0),
        p_range("glynns3subfl_thickness", 0.42, 0.0, 1.0),
        p_range("glynns3subfl_contrast", 1.0, 0.0, 1.0),
        p("glynns3subfl_pow", 1.5),
        p_int("glynns3subfl_type", 0.0, -2147483648.0, 2147483647.0),
        p("glynns3subfl_phi1", 0.0),
        p("glynns3subfl_phi2", 360.0),
    ];
    join::<9, 12, 21>(own, subflame_params!("glynns3subfl", 0.0))
};

/// `a` then `b` (N = A + B).
const fn join<const A: usize, const B: usize, const N: usize>(
    a: [Param; A],
    b: [Param; B],
) -> [Param; N] {
    let mut out = [a[0]; N];
    let mut i = 0;
    while i < A {
        out[i] = a[i];
        i += 1;
    }
    while i < N {
        out[i] = b[i - A];
        i += 1;
    }
    out
}

/// What every sub-flame variation is: random, stateful (the chaos game's point), and able to
/// colour and hide the point.
const SUBFLAME: u32 = flag::JWILDFIRE
    | flag::RANDOM
    | flag::STATEFUL
    | flag::WRITES_Z
    | flag::SETS_COLOR
    | flag::HIDES;

/// subflame_wf: the sub-flame's next point (not weighted), added to the sum; a hidden point
/// when the sub-flame draws none.
fn subflame_wf(v: &Prepared, _t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    match sub_point(v, 0, acc, rng) {
        Some(q) => [q.x, q.y, q.z],
        None => {
            acc.hide = true;
            [0.0; 3]
        }
    }
}

/// pre_subflame_wf: the sub-flame's next point replaces the affine point.
fn pre_subflame_wf(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    match sub_point(v, 0, acc, rng) {
        Some(q) => [q.x, q.y, q.z],
        None => {
            acc.hide = true;
            [t.x, t.y, t.z]
        }
    }
}

/// State slots of ringsubflame's last output (x, y), after the chaos game's.
const ST_OLD: usize = 6;

/// ringsubflame (JWildfire's `RingSubFlameFunc`): the sub-flame's point, inside a ring
/// (inner radius `innerradius` + `thickness`) replaced by a point of the ring's two circles
/// (or, with `hide_inner`, the last output), outside it pushed in towards the ring with a
/// probability `contrast`·(radius/r)^|pow|; the sum is then scaled by the weight and cut at
/// `outerradius` (hidden there with `hide_outer`, else put on a circle scattered by
/// `scatter_area`).
fn ringsubflame(v: &Prepared, _t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [hide, radius, crop, thickness, contrast, pow, scatter, zero] = v.params();
    let w = v.w;
    // JWildfire colours the point last (`setColor` ends `transform`), and not at all when the
    // crop below hides it: such a point keeps the colour it came with.
    let (color_in, rgb_in) = (acc.color, acc.rgb);
    let Some(q) = sub_point(v, 8, acc, rng) else {
        acc.hide = true;
        return [0.0; 3];
    };
    let r1 = radius + thickness;
    let r2 = radius * radius / r1;
    let gamma = r1 / (r1 + r2);
    let r = q.x.hypot(q.y);
    let alpha = radius / r;
    if r < r1 {
        if hide == 0.0 {
            let (s, c) = (2.0 * PI * rng.f01()).sin_cos();
            let rr = if rng.f01() < gamma { r1 } else { r2 };
            acc.x += w * rr * c;
            acc.y += w * rr * s;
        } else {
            acc.x = v.state.get(ST_OLD);
            acc.y = v.state.get(ST_OLD + 1);
        }
    } else if rng.f01() > contrast * alpha.powf(pow.abs()) {
        acc.x += w * q.x;
        acc.y += w * q.y;
    } else {
        acc.x += w * alpha * alpha * q.x;
        acc.y += w * alpha * alpha * q.y;
    }
    v.state.set(ST_OLD, acc.x);
    v.state.set(ST_OLD + 1, acc.y);
    let rad = acc.x.hypot(acc.y);
    let (s, c) = acc.y.atan2(acc.x).sin_cos();
    let rdc = crop + rng.f01() * 0.5 * scatter.clamp(-1.0, 1.0);
    let esc = rad > crop;
    if zero == 1.0 && esc {
        acc.x = 0.0;
        acc.y = 0.0;
        acc.hide = true;
        (acc.color, acc.rgb) = (color_in, rgb_in);
    } else if esc {
        acc.x = w * rdc * c;
        acc.y = w * rdc * s;
    } else {
        acc.x *= w;
        acc.y *= w;
    }
    [0.0; 3]
}

/// glynns3subfl (JWildfire's `GlynnS3SubflWFFunc`): with probability `weight` Glynn's ring
/// (points inside the circle of `radius` + `thickness` moved onto the ring, or, with `type`
/// not 0, onto an arc from `phi1` to `phi2` degrees; points outside pushed in with a
/// probability `contrast`·(radius/r)^|pow|) replaces the sum; else the sub-flame's point,
/// weighted, is added.
fn glynns3subfl(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [
        weight,
        show,
        radius,
        thickness,
        contrast,
        pow,
        kind,
        phi1,
        phi2,
    ] = v.params();
    let w = v.w;
    let r = t.x.hypot(t.y);
    let alpha = radius / r;
    let abs_pow = pow.abs();
    let (mut nx, mut ny) = (0.0, 0.0);
    let (inner, circle): (f64, [f64; 2]) = if kind != 0.0 {
        let gamma = thickness * (2.0 * radius + thickness) / (radius + thickness);
        (radius, [gamma, 0.0])
    } else {
        let r1 = radius + thickness;
        let r2 = radius * radius / r1;
        (r1, [r1 / (r1 + r2), r2])
    };
    if r < inner {
        if show == 1.0 {
            let (rr, phi) = if kind != 0.0 {
                let rr = radius + thickness - circle[0] * rng.f01();
                let (p1, p2) = (PI * phi1 / 180.0, PI * phi2 / 180.0);
                (rr, p1 + (p2 - p1) * rng.f01())
            } else {
                let phi = 2.0 * PI * rng.f01();
                (
                    if rng.f01() < circle[0] {
                        inner
                    } else {
                        circle[1]
                    },
                    phi,
                )
            };
            let (s, c) = phi.sin_cos();
            nx += w * rr * c;
            ny += w * rr * s;
        } else {
            nx += w * t.x;
            ny += w * t.y;
        }
    } else if rng.f01() > contrast * alpha.powf(abs_pow) {
        nx += w * t.x;
        ny += w * t.y;
    } else {
        nx += w * alpha * alpha * t.x;
        ny += w * alpha * alpha * t.y;
    }
    if rng.f01() < weight {
        acc.x = nx;
        acc.y = ny;
        return [0.0, 0.0, v.default_z(t)];
    }
    match sub_point(v, 9, acc, rng) {
        Some(q) => [w * q.x, w * q.y, w * q.z],
        None => {
            acc.hide = true;
            [0.0; 3]
        }
    }
}
