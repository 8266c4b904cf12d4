//! Render state files (`.ugnis-state`): a flame render's histogram and everything needed to
//! continue it or merge it with other parts of the same render.
//!
//! Layout (little-endian):
//!
//! ```text
//! "UGNISRS\x1a"                        8-byte magic
//! u32 version                          FORMAT_VERSION
//! u32 n, n bytes                       header: UTF-8 lines "key value", then "flame" and the
//!                                      flame's XML element on the following lines
//! u32 k, k × lane set                  each worker's orbits: 256 × (x, y, z, c as f64, last
//!                                      as u16, consec as u8, step as i32), then started as u8
//! repeated: "ROWS" u32 row0 u32 rows u64 n, n bytes
//!                                      bucket rows row0.. of the grid: deflate of a bit per
//!                                      bucket (empty or not), then the non-empty buckets'
//!                                      alphas and colours as byte planes (see `compress`)
//! "END\0" u32 chunk count              the end (a truncated file has none)
//! ```
//!
//! The chunks tile the bucket rows in order, so a reader can fetch any band of rows without
//! holding the whole histogram (renders in strips, merges of posters).

use std::fs::File;
use std::io::{BufReader, BufWriter, Read, Seek, SeekFrom, Write};
use std::ops::Range;
use std::path::Path;

use rayon::prelude::*;

use crate::flame::chaos::{LANES, LaneState};
use crate::flame::histogram::{Bucket, Histogram};
use crate::flame::render::{RenderOptions, Renderer};
use crate::flame::state::{MAX_PARTS, RenderState};
use crate::flame::strips::Strip;
use crate::io::diag::{Diagnostic, Pos};

pub const MAGIC: &[u8; 8] = b"UGNISRS\x1a";
/// The version this ugnis writes and reads.
/// 2: colours in palette units (whole numbers for 8-bit palettes), stored as integers when
/// whole. Version 1 held them in units of 1.0.
pub const FORMAT_VERSION: u32 = 2;
/// Rows per compressed chunk.
pub const CHUNK_ROWS: usize = 32;
const MAX_HEADER: u32 = 64 << 20;
const MAX_LANE_SETS: u32 = 4096;
const LANE_SET_BYTES: usize = LANES * (4 * 8 + 2 + 1 + 4) + 1;

fn err(file: &str, pos: Pos, msg: impl Into<String>) -> Diagnostic {
    Diagnostic::error(file, pos, "STATE001", msg)
}

fn io_err(file: &str, e: std::io::Error) -> Diagnostic {
    if e.kind() == std::io::ErrorKind::UnexpectedEof {
        err(
            file,
            Pos::File,
            "the file ends early (truncated: was it still being written?)",
        )
    } else {
        err(file, Pos::File, format!("cannot read: {e}"))
    }
}

/// The header text of a state.
fn header_text(st: &RenderState, grid: (usize, usize)) -> String {
    let parts: Vec<String> = st.parts.iter().map(|p| p.to_string()).collect();
    format!(
        "ugnis-render-state\nugnis {}\nseed {}\nparts {} of {}\nbatches_done {}\nsamples_done {}\nbad_values {}\nbuckets {}x{}\nflame\n{}\n",
        crate::VERSION,
        st.seed,
        parts.join(","),
        st.part_count,
        st.batches_done,
        st.samples_done,
        st.bad_values,
        grid.0,
        grid.1,
        crate::io::flam3_xml::flame_element(&st.flame)
    )
}

/// Check that a state's flame survives the trip through its XML (3-D IFS flames, for one, have
/// no XML form).
pub fn check_saveable(st: &RenderState) -> Result<(), String> {
    if st.flame.ifs3d.is_some() {
        return Err("a render state of a 3-D IFS cannot be saved (its maps have no flame XML form); render it in one go".into());
    }
    Ok(())
}

/// Writes a state: header and orbits at once, then the histogram rows in order.
pub struct StateWriter<W: Write> {
    out: W,
    bw: usize,
    bh: usize,
    next_row: usize,
    chunks: u32,
}

impl<W: Write> StateWriter<W> {
    pub fn new(mut out: W, st: &RenderState) -> std::io::Result<StateWriter<W>> {
        check_saveable(st).map_err(std::io::Error::other)?;
        let (bw, bh) = st.grid().map_err(std::io::Error::other)?;
        let header = header_text(st, (bw, bh));
        out.write_all(MAGIC)?;
        out.write_all(&FORMAT_VERSION.to_le_bytes())?;
        out.write_all(&(header.len() as u32).to_le_bytes())?;
        out.write_all(header.as_bytes())?;
        out.write_all(&(st.lanes.len() as u32).to_le_bytes())?;
        for l in &st.lanes {
            let mut b = Vec::with_capacity(LANE_SET_BYTES);
            for v in [&l.x, &l.y, &l.z, &l.c] {
                for x in v.iter() {
                    b.extend_from_slice(&x.to_le_bytes());
                }
            }
            for x in &l.last {
                b.extend_from_slice(&x.to_le_bytes());
            }
            b.extend_from_slice(&l.consec);
            for x in &l.step {
                b.extend_from_slice(&x.to_le_bytes());
            }
            b.push(l.started as u8);
            if b.len() != LANE_SET_BYTES {
                return Err(std::io::Error::other("orbit state of the wrong size"));
            }
            out.write_all(&b)?;
        }
        Ok(StateWriter {
            out,
            bw,
            bh,
            next_row: 0,
            chunks: 0,
        })
    }

    /// Append the next rows (`data` holds whole rows of the bucket grid, following those
    /// written before). Compressed in parallel chunks.
    pub fn write_rows(&mut self, data: &[Bucket]) -> std::io::Result<()> {
        let bw = self.bw;
        if !data.len().is_multiple_of(bw) || self.next_row + data.len() / bw > self.bh {
            return Err(std::io::Error::other("histogram rows do not fit the grid"));
        }
        // Compress a group of chunks in parallel, then write them in order.
        let group = CHUNK_ROWS * bw * rayon::current_num_threads().max(1) * 2;
        for part in data.chunks(group) {
            let packed: Vec<Vec<u8>> = part
                .par_chunks(CHUNK_ROWS * bw)
                .map(compress)
                .collect::<std::io::Result<_>>()?;
            for (rows, bytes) in part.chunks(CHUNK_ROWS * bw).zip(packed) {
                let n = rows.len() / bw;
                self.out.write_all(b"ROWS")?;
                self.out.write_all(&(self.next_row as u32).to_le_bytes())?;
                self.out.write_all(&(n as u32).to_le_bytes())?;
                self.out.write_all(&(bytes.len() as u64).to_le_bytes())?;
                self.out.write_all(&bytes)?;
                self.next_row += n;
                self.chunks += 1;
            }
        }
        Ok(())
    }

    /// End the file; every row must have been written.
    pub fn finish(mut self) -> std::io::Result<W> {
        if self.next_row != self.bh {
            return Err(std::io::Error::other(format!(
                "only {} of {} histogram rows were written",
                self.next_row, self.bh
            )));
        }
        self.out.write_all(b"END\0")?;
        self.out.write_all(&self.chunks.to_le_bytes())?;
        self.out.flush()?;
        Ok(self.out)
    }
}

/// Byte planes: all the lowest bytes of `words`, then the next…
fn shuffle_into(out: &mut Vec<u8>, words: &[u32]) {
    for k in 0..4 {
        out.extend(words.iter().map(|w| (w >> (8 * k)) as u8));
    }
}

fn unshuffle(bytes: &[u8], n: usize) -> Vec<u32> {
    (0..n)
        .map(|i| u32::from_le_bytes([bytes[i], bytes[n + i], bytes[2 * n + i], bytes[3 * n + i]]))
        .collect()
}

/// Can this accumulator be stored as a whole number (and read back bit for bit)?
fn integral(a: f32) -> bool {
    (0.0..=16_777_216.0).contains(&a) && (a as u32 as f32).to_bits() == a.to_bits()
}

/// Flags of a chunk: its alphas, its colours are whole numbers stored as integers.
const WHOLE_ALPHAS: u8 = 1;
const WHOLE_COLOURS: u8 = 2;

/// The words of accumulators: whole numbers as integers (high bytes mostly zero), else bits.
fn words(values: impl Iterator<Item = f32>, whole: bool) -> Vec<u32> {
    values
        .map(|v| if whole { v as u32 } else { v.to_bits() })
        .collect()
}

fn floats(words: Vec<u32>, whole: bool) -> Vec<f32> {
    words
        .into_iter()
        .map(|w| if whole { w as f32 } else { f32::from_bits(w) })
        .collect()
}

/// A chunk before deflate: a bit per bucket (set: not all zero), flags (whole alphas — hit
/// counts of opaque palettes — and whole colours — sums of 8-bit palette entries — stored as
/// integers), the alphas of the set buckets, then their R, G, B, each as byte planes. Empty
/// buckets cost one bit; the noisy low mantissa bytes are kept apart from the exponents.
fn compress(rows: &[Bucket]) -> std::io::Result<Vec<u8>> {
    let n = rows.len();
    let mut mask = vec![0u8; n.div_ceil(8)];
    let mut kept: Vec<&Bucket> = Vec::new();
    for (i, b) in rows.iter().enumerate() {
        if b.iter().any(|v| v.to_bits() != 0) {
            mask[i / 8] |= 1 << (i % 8);
            kept.push(b);
        }
    }
    let whole_a = kept.iter().all(|b| integral(b[3]));
    let whole_c = kept.iter().all(|b| b[..3].iter().all(|&v| integral(v)));
    let mut buf = Vec::with_capacity(mask.len() + 1 + kept.len() * 16);
    buf.extend_from_slice(&mask);
    buf.push(if whole_a { WHOLE_ALPHAS } else { 0 } | if whole_c { WHOLE_COLOURS } else { 0 });
    shuffle_into(&mut buf, &words(kept.iter().map(|b| b[3]), whole_a));
    let rgb = kept.iter().flat_map(|b| [b[0], b[1], b[2]]);
    shuffle_into(&mut buf, &words(rgb, whole_c));
    let mut enc = flate2::write::DeflateEncoder::new(
        Vec::with_capacity(buf.len() / 2),
        flate2::Compression::fast(),
    );
    enc.write_all(&buf)?;
    enc.finish()
}

fn decompress(file: &str, at: u64, bytes: &[u8], out: &mut [Bucket]) -> Result<(), Diagnostic> {
    let n = out.len();
    let damaged = |m: String| err(file, Pos::Byte(at), format!("damaged histogram chunk: {m}"));
    let limit = n.div_ceil(8) + 1 + n * 16;
    let mut buf = Vec::with_capacity(limit);
    flate2::read::DeflateDecoder::new(bytes)
        .take(limit as u64 + 1)
        .read_to_end(&mut buf)
        .map_err(|e| damaged(e.to_string()))?;
    let mlen = n.div_ceil(8);
    if buf.len() < mlen + 1 {
        return Err(damaged("too short".into()));
    }
    let m = (0..n).filter(|&i| buf[i / 8] & (1 << (i % 8)) != 0).count();
    if buf.len() != mlen + 1 + 16 * m {
        return Err(damaged(format!(
            "{} bytes where {} were expected",
            buf.len(),
            mlen + 1 + 16 * m
        )));
    }
    let flags = buf[mlen];
    if flags & !(WHOLE_ALPHAS | WHOLE_COLOURS) != 0 {
        return Err(damaged(format!("unknown accumulator encoding {flags}")));
    }
    let alpha = floats(
        unshuffle(&buf[mlen + 1..mlen + 1 + 4 * m], m),
        flags & WHOLE_ALPHAS != 0,
    );
    let rgb = floats(
        unshuffle(&buf[mlen + 1 + 4 * m..], 3 * m),
        flags & WHOLE_COLOURS != 0,
    );
    let mut k = 0;
    for (i, o) in out.iter_mut().enumerate() {
        if buf[i / 8] & (1 << (i % 8)) == 0 {
            *o = [0.0; 4];
            continue;
        }
        *o = [rgb[3 * k], rgb[3 * k + 1], rgb[3 * k + 2], alpha[k]];
        k += 1;
    }
    Ok(())
}

/// Save a whole state atomically.
pub fn save(path: &Path, st: &RenderState, hist: &Histogram) -> std::io::Result<()> {
    crate::io::atomic::write_atomic_with(path, |f| {
        let mut w = StateWriter::new(BufWriter::new(f), st)?;
        w.write_rows(&hist.data)?;
        w.finish()?;
        Ok(())
    })
}

struct Chunk {
    row0: usize,
    rows: usize,
    offset: u64,
    len: u64,
}

/// An open state file: the state, and its histogram rows on demand.
pub struct StateReader {
    file_name: String,
    file: BufReader<File>,
    pub state: RenderState,
    /// Bucket grid: width and height.
    pub bw: usize,
    pub bh: usize,
    chunks: Vec<Chunk>,
}

/// Read one line "key value" of the header.
fn field<'a>(
    lines: &[(usize, &'a str)],
    k: usize,
    key: &str,
    file: &str,
) -> Result<&'a str, Diagnostic> {
    let (ln, text) = lines.get(k).copied().unwrap_or((lines.len() + 1, ""));
    text.strip_prefix(key)
        .and_then(|r| r.strip_prefix(' '))
        .ok_or_else(|| {
            err(
                file,
                Pos::File,
                format!("header line {ln}: expected '{key} …', found '{text}'"),
            )
        })
}

fn num<T: std::str::FromStr>(v: &str, key: &str, file: &str) -> Result<T, Diagnostic> {
    v.trim().parse().map_err(|_| {
        err(
            file,
            Pos::File,
            format!("header field '{key}': '{v}' is not a whole number in range"),
        )
    })
}

impl StateReader {
    /// Open a state file: check the magic and version, read the header and orbits, and index
    /// the histogram chunks (checking that they tile the grid and that the file is complete).
    pub fn open(path: &Path) -> Result<StateReader, Diagnostic> {
        let name = path.display().to_string();
        let (f, meta) = crate::io::open_regular(path)?;
        let len = meta.len();
        let mut file = BufReader::new(f);
        let e = |x| io_err(&name, x);
        let mut magic = [0u8; 8];
        file.read_exact(&mut magic).map_err(|_| {
            err(
                &name,
                Pos::File,
                "not a ugnis render state (the file is too short)",
            )
        })?;
        if &magic != MAGIC {
            return Err(err(
                &name,
                Pos::Byte(0),
                "not a ugnis render state (it does not start with UGNISRS); states are written by `ugnis render --save-state`",
            ));
        }
        let version = read_u32(&mut file).map_err(e)?;
        if version != FORMAT_VERSION {
            return Err(err(
                &name,
                Pos::Byte(8),
                format!(
                    "render state format version {version}, but ugnis {} reads version {FORMAT_VERSION} only; render the part again with this ugnis (a state cannot be converted: its histogram layout differs between versions)",
                    crate::VERSION
                ),
            ));
        }
        let hlen = read_u32(&mut file).map_err(e)?;
        if hlen > MAX_HEADER || hlen as u64 > len {
            return Err(err(
                &name,
                Pos::Byte(12),
                format!(
                    "header of {hlen} bytes is longer than the file or the limit of {MAX_HEADER}"
                ),
            ));
        }
        let mut hbytes = vec![0u8; hlen as usize];
        file.read_exact(&mut hbytes).map_err(e)?;
        let text = String::from_utf8(hbytes)
            .map_err(|_| err(&name, Pos::Byte(16), "the header is not UTF-8 text"))?;
        let (state, bw, bh) = parse_header(&text, &name)?;
        let n_lanes = read_u32(&mut file).map_err(e)?;
        if n_lanes > MAX_LANE_SETS {
            return Err(err(
                &name,
                Pos::File,
                format!("{n_lanes} orbit sets (limit {MAX_LANE_SETS})"),
            ));
        }
        let mut state = state;
        for _ in 0..n_lanes {
            let mut b = vec![0u8; LANE_SET_BYTES];
            file.read_exact(&mut b).map_err(e)?;
            state.lanes.push(parse_lanes(&b));
        }
        // Index the chunks.
        let mut chunks = Vec::new();
        let mut pos = file.stream_position().map_err(e)?;
        let mut next_row = 0usize;
        loop {
            let mut tag = [0u8; 4];
            file.read_exact(&mut tag).map_err(e)?;
            if &tag == b"END\0" {
                let count = read_u32(&mut file).map_err(e)?;
                if count as usize != chunks.len() || next_row != bh {
                    return Err(err(
                        &name,
                        Pos::Byte(pos),
                        format!(
                            "the histogram is incomplete: {next_row} of {bh} rows in {} chunks (the end marker says {count})",
                            chunks.len()
                        ),
                    ));
                }
                break;
            }
            if &tag != b"ROWS" {
                return Err(err(
                    &name,
                    Pos::Byte(pos),
                    "expected a histogram chunk (ROWS)",
                ));
            }
            let row0 = read_u32(&mut file).map_err(e)? as usize;
            let rows = read_u32(&mut file).map_err(e)? as usize;
            let clen = read_u64(&mut file).map_err(e)?;
            let offset = pos + 20;
            if offset + clen > len {
                return Err(err(
                    &name,
                    Pos::Byte(pos),
                    format!(
                        "histogram chunk of rows {row0}..{} runs past the end of the file (truncated: was it still being written?)",
                        row0 + rows
                    ),
                ));
            }
            if row0 != next_row || rows == 0 || row0 + rows > bh {
                return Err(err(
                    &name,
                    Pos::Byte(pos),
                    format!(
                        "histogram chunk of rows {row0}..{} does not follow row {next_row} of {bh}",
                        row0 + rows
                    ),
                ));
            }
            chunks.push(Chunk {
                row0,
                rows,
                offset,
                len: clen,
            });
            next_row += rows;
            pos = offset + clen;
            file.seek(SeekFrom::Start(pos)).map_err(e)?;
        }
        Ok(StateReader {
            file_name: name,
            file,
            state,
            bw,
            bh,
            chunks,
        })
    }

    pub fn file_name(&self) -> &str {
        &self.file_name
    }

    /// Compressed size of the histogram.
    pub fn compressed_bytes(&self) -> u64 {
        self.chunks.iter().map(|c| c.len).sum()
    }

    /// Bucket rows `rows` of the grid as a histogram of `bw` × `rows.len()` buckets.
    pub fn read_rows(&mut self, rows: Range<usize>) -> Result<Histogram, Diagnostic> {
        self.check_rows(&rows)?;
        let mut h = Histogram::new(self.bw, rows.len());
        self.read_rows_into(rows, &mut h)?;
        Ok(h)
    }

    fn check_rows(&self, rows: &Range<usize>) -> Result<(), Diagnostic> {
        if rows.end > self.bh || rows.start > rows.end {
            return Err(err(
                &self.file_name,
                Pos::File,
                format!("rows {rows:?} are outside the grid of {} rows", self.bh),
            ));
        }
        Ok(())
    }

    /// [`StateReader::read_rows`] into `h` (`bw` × the rows' count buckets), inflating each
    /// chunk in place (in parallel): the histogram is never held twice.
    pub fn read_rows_into(
        &mut self,
        rows: Range<usize>,
        h: &mut Histogram,
    ) -> Result<(), Diagnostic> {
        let name = self.file_name.clone();
        self.check_rows(&rows)?;
        let bw = self.bw;
        if (h.bw, h.bh) != (bw, rows.len()) {
            return Err(err(
                &name,
                Pos::File,
                format!(
                    "the saved histogram has {bw}×{} buckets there, the render needs {}×{}",
                    rows.len(),
                    h.bw,
                    h.bh
                ),
            ));
        }
        // Read the compressed chunks that meet the range (they tile the rows in order).
        let mut raw: Vec<(usize, usize, u64, Vec<u8>)> = Vec::new();
        for c in &self.chunks {
            if c.row0 + c.rows <= rows.start || c.row0 >= rows.end {
                continue;
            }
            self.file
                .seek(SeekFrom::Start(c.offset))
                .map_err(|e| io_err(&name, e))?;
            let mut b = vec![0u8; c.len as usize];
            self.file.read_exact(&mut b).map_err(|e| io_err(&name, e))?;
            raw.push((c.row0, c.rows, c.offset, b));
        }
        // Each chunk's share of `h`: whole chunks are inflated straight into it, the (at most
        // two) chunks cut by the range's ends through a buffer of their own.
        let mut jobs = Vec::with_capacity(raw.len());
        let mut rest: &mut [Bucket] = &mut h.data;
        let mut next = rows.start;
        for (row0, n, at, b) in &raw {
            let (lo, hi) = ((*row0).max(rows.start), (row0 + n).min(rows.end));
            let (_, tail) = rest.split_at_mut((lo - next) * bw);
            let (dst, tail) = tail.split_at_mut((hi - lo) * bw);
            rest = tail;
            next = hi;
            jobs.push((*row0, *n, *at, b, lo, dst));
        }
        jobs.into_par_iter()
            .try_for_each(|(row0, n, at, b, lo, dst)| {
                if dst.len() == n * bw {
                    decompress(&name, at, b, dst)
                } else {
                    let mut out = vec![[0f32; 4]; n * bw];
                    decompress(&name, at, b, &mut out)?;
                    let from = (lo - row0) * bw;
                    dst.copy_from_slice(&out[from..from + dst.len()]);
                    Ok(())
                }
            })
    }

    /// The whole histogram.
    pub fn read_all(&mut self) -> Result<Histogram, Diagnostic> {
        self.read_rows(0..self.bh)
    }

    /// A renderer that continues this state with `add_quality` more samples per pixel, for
    /// the whole image or (reading only its rows) one strip of it. Errors name the file.
    pub fn renderer(
        &mut self,
        add_quality: f64,
        opts: &RenderOptions,
        strip: Option<Strip>,
    ) -> Result<Renderer, String> {
        let rows = match &strip {
            Some(s) => s.hist_rows.clone(),
            None => 0..self.bh,
        };
        let state = self.state.clone();
        // The renderer checks the memory it needs before it allocates; the saved buckets are
        // then read into its first histogram.
        Renderer::resume_with(&state, add_quality, opts, strip, |h| {
            self.read_rows_into(rows, h).map_err(|e| e.to_string())
        })
        .map_err(|e| format!("cannot continue '{}': {e}", self.file_name))
    }
}

fn read_u32(r: &mut impl Read) -> std::io::Result<u32> {
    let mut b = [0u8; 4];
    r.read_exact(&mut b)?;
    Ok(u32::from_le_bytes(b))
}

fn read_u64(r: &mut impl Read) -> std::io::Result<u64> {
    let mut b = [0u8; 8];
    r.read_exact(&mut b)?;
    Ok(u64::from_le_bytes(b))
}

fn parse_lanes(b: &[u8]) -> LaneState {
    let mut at = 0usize;
    let mut f64s = || {
        let v: Vec<f64> = (0..LANES)
            .map(|i| {
                let o = at + 8 * i;
                f64::from_le_bytes(b[o..o + 8].try_into().unwrap_or([0; 8]))
            })
            .collect();
        at += 8 * LANES;
        v
    };
    let (x, y, z, c) = (f64s(), f64s(), f64s(), f64s());
    let mut at = 4 * 8 * LANES;
    let last = (0..LANES)
        .map(|i| u16::from_le_bytes([b[at + 2 * i], b[at + 2 * i + 1]]))
        .collect();
    at += 2 * LANES;
    let consec = b[at..at + LANES].to_vec();
    at += LANES;
    let step = (0..LANES)
        .map(|i| {
            let o = at + 4 * i;
            i32::from_le_bytes([b[o], b[o + 1], b[o + 2], b[o + 3]])
        })
        .collect();
    at += 4 * LANES;
    LaneState {
        x,
        y,
        z,
        c,
        last,
        consec,
        step,
        started: b[at] != 0,
    }
}

fn parse_header(text: &str, file: &str) -> Result<(RenderState, usize, usize), Diagnostic> {
    let lines: Vec<(usize, &str)> = text.lines().enumerate().map(|(i, l)| (i + 1, l)).collect();
    if lines.first().map(|l| l.1) != Some("ugnis-render-state") {
        return Err(err(
            file,
            Pos::File,
            "header line 1: expected 'ugnis-render-state'",
        ));
    }
    let _writer = field(&lines, 1, "ugnis", file)?;
    let seed: u64 = num(field(&lines, 2, "seed", file)?, "seed", file)?;
    let parts_text = field(&lines, 3, "parts", file)?;
    let (list, count) = parts_text.split_once(" of ").ok_or_else(|| {
        err(
            file,
            Pos::File,
            format!("header line 4: expected 'parts I,J,… of N', found 'parts {parts_text}'"),
        )
    })?;
    let part_count: u32 = num(count, "parts", file)?;
    let mut parts: Vec<u32> = list
        .split(',')
        .map(|p| num(p, "parts", file))
        .collect::<Result<_, _>>()?;
    parts.sort_unstable();
    parts.dedup();
    if part_count == 0 || part_count > MAX_PARTS || parts.iter().any(|&p| p >= part_count) {
        return Err(err(
            file,
            Pos::File,
            format!(
                "header line 4: parts {list} of {part_count} are out of range (1 to {MAX_PARTS} parts, numbered from 0)"
            ),
        ));
    }
    let batches_done = num(
        field(&lines, 4, "batches_done", file)?,
        "batches_done",
        file,
    )?;
    let samples_done = num(
        field(&lines, 5, "samples_done", file)?,
        "samples_done",
        file,
    )?;
    let bad_values = num(field(&lines, 6, "bad_values", file)?, "bad_values", file)?;
    let grid = field(&lines, 7, "buckets", file)?;
    let (gw, gh) = grid
        .split_once('x')
        .ok_or_else(|| err(file, Pos::File, "header line 8: expected 'buckets WxH'"))?;
    let (bw, bh): (usize, usize) = (num(gw, "buckets", file)?, num(gh, "buckets", file)?);
    if lines.get(8).map(|l| l.1) != Some("flame") {
        return Err(err(file, Pos::File, "header line 9: expected 'flame'"));
    }
    let start = text
        .match_indices('\n')
        .nth(8)
        .map_or(text.len(), |(i, _)| i + 1);
    let opts = crate::io::flam3_xml::ReadOptions {
        file: format!("{file} (header)"),
        ..Default::default()
    };
    let parsed = crate::io::flam3_xml::read(&text[start..], &opts)?;
    let Some(mut flame) = parsed.value.flames.into_iter().next() else {
        return Err(err(file, Pos::File, "the header holds no flame"));
    };
    flame.has_camera = true;
    let state = RenderState {
        flame,
        seed,
        part_count,
        parts,
        batches_done,
        samples_done,
        bad_values,
        lanes: Vec::new(),
    };
    let want = state.grid().map_err(|m| {
        err(
            file,
            Pos::File,
            format!("the flame cannot be rendered: {m}"),
        )
    })?;
    if want != (bw, bh) {
        return Err(err(
            file,
            Pos::File,
            format!(
                "the header says {bw}x{bh} buckets but its flame needs {}x{}",
                want.0, want.1
            ),
        ));
    }
    if bw.saturating_mul(bh) > u32::MAX as usize {
        return Err(err(file, Pos::File, "the bucket grid is too large"));
    }
    Ok((state, bw, bh))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Chunks come back bit for bit whatever their values: whole colours and alphas (stored as
    /// integers), fractional ones, both mixed in one chunk, and the edge of f32's whole numbers.
    #[test]
    fn chunks_round_trip_bit_for_bit() {
        let mut rng = crate::flame::rng::FastRng::new(5);
        let whole = |rng: &mut crate::flame::rng::FastRng| -> Bucket {
            let n = (rng.f01() * 60.0).floor() as f32;
            let c = |rng: &mut crate::flame::rng::FastRng| (rng.f01() * 255.0).floor() as f32 * n;
            [c(rng), c(rng), c(rng), n]
        };
        let cases: Vec<Vec<Bucket>> = vec![
            (0..500).map(|_| whole(&mut rng)).collect(),
            (0..500)
                .map(|i| {
                    let mut b = whole(&mut rng);
                    if i == 250 {
                        b[1] += 0.5; // one fractional colour: the chunk stores bits
                    }
                    b
                })
                .collect(),
            (0..500)
                .map(|_| [rng.f01() as f32, 0.3, 1e-9, rng.f01() as f32 * 7.0])
                .collect(),
            vec![
                [16_777_216.0, 16_777_215.0, 0.0, 1.0],
                [0.0; 4],
                [1.0, 2.0, 3.0, 16_777_216.0],
            ],
            vec![[-1.0, 2.0, f32::NAN, 4.0], [1e30, 0.0, 0.0, -0.0]],
        ];
        for rows in cases {
            let bytes = compress(&rows).unwrap();
            let mut back = vec![[9.0f32; 4]; rows.len()];
            decompress("t", 0, &bytes, &mut back).unwrap();
            for (a, b) in rows.iter().zip(&back) {
                assert_eq!(a.map(f32::to_bits), b.map(f32::to_bits));
            }
        }
    }

    /// Rows cut out of the middle of chunks (32 rows each) read as the same rows of the whole
    /// histogram, bit for bit; a destination of the wrong size is refused.
    #[test]
    fn a_band_of_rows_reads_as_the_same_rows_of_the_whole() {
        use crate::flame::render::{RenderOptions, Renderer};
        let f = crate::flame::model::test_sierpinski(40, 90, 3.0);
        let mut r = Renderer::new(&f, &RenderOptions::default()).unwrap();
        assert!(r.run_all(1, &std::sync::atomic::AtomicBool::new(false), |_| {}));
        let (st, hist) = r.into_state().unwrap();
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("s.ugnis-state");
        save(&path, &st, &hist).unwrap();
        let mut rd = StateReader::open(&path).unwrap();
        let all = rd.read_all().unwrap();
        assert_eq!(all.data, hist.data);
        let bw = hist.bw;
        for rows in [10..75, 0..32, 31..33, 64..hist.bh, 40..40] {
            let band = rd.read_rows(rows.clone()).unwrap();
            assert_eq!(
                band.data,
                hist.data[rows.start * bw..rows.end * bw],
                "{rows:?}"
            );
        }
        let mut wrong = Histogram::new(bw, 5);
        let e = rd
            .read_rows_into(10..20, &mut wrong)
            .unwrap_err()
            .to_string();
        assert!(e.contains("s.ugnis-state") && e.contains("buckets"), "{e}");
        assert!(rd.read_rows(80..hist.bh + 1).is_err());
    }

    /// Sums of 8-bit palette entries (whole palette units) take far less room than the same
    /// colours in units of 1.0, as version 1 stored them.
    #[test]
    fn whole_colours_compress_better_than_their_fractions() {
        let mut rng = crate::flame::rng::FastRng::new(8);
        let rows: Vec<Bucket> = (0..4096)
            .map(|_| {
                let n = 1.0 + (rng.f01() * 40.0).floor();
                let mut c = [0.0f64; 3];
                for _ in 0..n as usize {
                    for v in &mut c {
                        *v += (rng.f01() * 256.0).floor().min(255.0);
                    }
                }
                [c[0] as f32, c[1] as f32, c[2] as f32, n as f32]
            })
            .collect();
        let units = compress(&rows).unwrap().len();
        let fractions: Vec<Bucket> = rows
            .iter()
            .map(|b| [b[0] / 255.0, b[1] / 255.0, b[2] / 255.0, b[3]])
            .collect();
        let ones = compress(&fractions).unwrap().len();
        let raw = rows.len() * 16;
        assert!(units * 10 < raw * 4, "{units} of {raw}");
        assert!(units * 10 < ones * 8, "{units} vs {ones}");
    }
}
