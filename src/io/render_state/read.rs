//! Reading a render state: the header, the orbits, and the histogram rows on demand (any
//! band of rows, decompressed in parallel).

use std::fs::File;
use std::io::{BufReader, Read, Seek, SeekFrom};
use std::ops::Range;
use std::path::Path;

use rayon::prelude::*;

use super::chunk::decompress;
use super::{
    FORMAT_VERSION, LANE_SET_BYTES, LANE_SET_BYTES_V2, MAGIC, MAX_HEADER, MAX_LANE_SETS,
    MAX_VAR_STATE, OLDEST_READ_VERSION, err, io_err,
};
use crate::flame::chaos::{LANES, LaneState};
use crate::flame::histogram::{Bucket, Histogram};
use crate::flame::render::{RenderOptions, Renderer};
use crate::flame::state::{MAX_PARTS, RenderState};
use crate::flame::strips::Strip;
use crate::io::diag::{Diagnostic, Pos};

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
    /// The render's state, without its histogram.
    pub state: RenderState,
    /// Width of the bucket grid.
    pub bw: usize,
    /// Height of the bucket grid (rows of the histogram).
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
        if !(OLDEST_READ_VERSION..=FORMAT_VERSION).contains(&version) {
            return Err(err(
                &name,
                Pos::Byte(8),
                format!(
                    "render state format version {version}, but ugnis {} reads versions {OLDEST_READ_VERSION} to {FORMAT_VERSION} only; render the part again with this ugnis (a state cannot be converted: its histogram layout differs between versions)",
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
        let (state, bw, bh) = parse_header(&text, &name, version)?;
        let n_lanes = read_u32(&mut file).map_err(e)?;
        if n_lanes > MAX_LANE_SETS {
            return Err(err(
                &name,
                Pos::File,
                format!("{n_lanes} orbit sets (limit {MAX_LANE_SETS})"),
            ));
        }
        let mut state = state;
        let set_bytes = if version >= 3 {
            LANE_SET_BYTES
        } else {
            LANE_SET_BYTES_V2
        };
        for _ in 0..n_lanes {
            let mut b = vec![0u8; set_bytes];
            file.read_exact(&mut b).map_err(e)?;
            state.lanes.push(parse_lanes(&b));
        }
        if version >= 4 {
            let n_sets = read_u32(&mut file).map_err(e)?;
            if n_sets > MAX_LANE_SETS {
                return Err(err(
                    &name,
                    Pos::File,
                    format!("{n_sets} variation states (limit {MAX_LANE_SETS})"),
                ));
            }
            for _ in 0..n_sets {
                let n = read_u32(&mut file).map_err(e)?;
                if n > MAX_VAR_STATE || n as u64 * 8 > len {
                    return Err(err(
                        &name,
                        Pos::File,
                        format!("a variation state of {n} values (limit {MAX_VAR_STATE})"),
                    ));
                }
                let mut b = vec![0u8; 8 * n as usize];
                file.read_exact(&mut b).map_err(e)?;
                state.var_states.push(
                    b.chunks_exact(8)
                        .map(|c| f64::from_le_bytes(c.try_into().unwrap_or([0; 8])))
                        .collect(),
                );
            }
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

    /// The file's name as shown in messages.
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
    let started = b[at] != 0;
    at += 1;
    // Version 3 on: own colours, hide flags and steps; a version 2 set ends here.
    let (rgb, hid, steps) = if b.len() >= at + 5 * LANES + 8 {
        let rgb = (0..LANES)
            .map(|i| {
                let o = at + 4 * i;
                u32::from_le_bytes([b[o], b[o + 1], b[o + 2], b[o + 3]])
            })
            .collect();
        at += 4 * LANES;
        let hid = b[at..at + LANES].iter().map(|&h| h != 0).collect();
        at += LANES;
        let steps = u64::from_le_bytes(b[at..at + 8].try_into().unwrap_or([0; 8]));
        (rgb, hid, steps)
    } else {
        (vec![0; LANES], vec![false; LANES], 0)
    };
    LaneState {
        x,
        y,
        z,
        c,
        last,
        consec,
        step,
        rgb,
        hid,
        steps,
        started,
    }
}

fn parse_header(
    text: &str,
    file: &str,
    version: u32,
) -> Result<(RenderState, usize, usize), Diagnostic> {
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
    // Version 4 on: the gap line follows.
    let (gap, at) = if version >= 4 {
        (num(field(&lines, 7, "gap", file)?, "gap", file)?, 8)
    } else {
        (0, 7)
    };
    // The skipped samples lie within the sub-batches done, of a render in one part.
    let gap_limit = if part_count == 1 {
        crate::flame::chaos::SUB_BATCH.saturating_mul(batches_done)
    } else {
        0
    };
    if gap > gap_limit {
        return Err(err(
            file,
            Pos::File,
            format!(
                "header line 8: gap {gap} is more than the {gap_limit} samples of the sub-batches done"
            ),
        ));
    }
    let grid = field(&lines, at, "buckets", file)?;
    let (gw, gh) = grid.split_once('x').ok_or_else(|| {
        err(
            file,
            Pos::File,
            format!("header line {}: expected 'buckets WxH'", at + 1),
        )
    })?;
    let (bw, bh): (usize, usize) = (num(gw, "buckets", file)?, num(gh, "buckets", file)?);
    if lines.get(at + 1).map(|l| l.1) != Some("flame") {
        return Err(err(
            file,
            Pos::File,
            format!("header line {}: expected 'flame'", at + 2),
        ));
    }
    let start = text
        .match_indices('\n')
        .nth(at + 1)
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
        var_states: Vec::new(),
        gap,
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
