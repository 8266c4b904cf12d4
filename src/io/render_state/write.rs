//! Writing a render state: the header and the orbits at once, then the histogram rows in
//! order as compressed chunks, then the end marker.

use std::io::Write;

use rayon::prelude::*;

use super::chunk::compress;
use super::{CHUNK_ROWS, FORMAT_VERSION, LANE_SET_BYTES, MAGIC, check_saveable};
use crate::flame::histogram::Bucket;
use crate::flame::render::save_chunks_in_flight;
use crate::flame::state::RenderState;

/// The header text of a state.
fn header_text(st: &RenderState, grid: (usize, usize)) -> String {
    let parts: Vec<String> = st.parts.iter().map(|p| p.to_string()).collect();
    format!(
        "ugnis-render-state\nugnis {}\nseed {}\nparts {} of {}\nbatches_done {}\nsamples_done {}\nbad_values {}\ngap {}\nbuckets {}x{}\nflame\n{}\n",
        crate::VERSION,
        st.seed,
        parts.join(","),
        st.part_count,
        st.batches_done,
        st.samples_done,
        st.bad_values,
        st.gap,
        grid.0,
        grid.1,
        crate::io::flam3_xml::flame_element(&st.flame)
    )
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
    /// Start a state file on `out`: check that the state can be saved and write its header and
    /// orbits (the histogram rows follow).
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
            for x in &l.rgb {
                b.extend_from_slice(&x.to_le_bytes());
            }
            b.extend(l.hid.iter().map(|&h| h as u8));
            b.extend_from_slice(&l.steps.to_le_bytes());
            if b.len() != LANE_SET_BYTES {
                return Err(std::io::Error::other("orbit state of the wrong size"));
            }
            out.write_all(&b)?;
        }
        out.write_all(&(st.var_states.len() as u32).to_le_bytes())?;
        for v in &st.var_states {
            let mut b = Vec::with_capacity(4 + 8 * v.len());
            b.extend_from_slice(&(v.len() as u32).to_le_bytes());
            for x in v {
                b.extend_from_slice(&x.to_le_bytes());
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
        // Compress a group of chunks in parallel, then write them in order: as many as the
        // memory estimate of a render allows for (see `save_chunks_in_flight`).
        let chunk_bytes = (CHUNK_ROWS * bw * std::mem::size_of::<Bucket>()) as u64;
        let in_flight = save_chunks_in_flight(chunk_bytes, rayon::current_num_threads());
        let group = CHUNK_ROWS * bw * in_flight;
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
