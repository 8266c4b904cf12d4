//! Animations out of ugnis: a video through ffmpeg (frames piped to it as raw pixels, an audio
//! track muxed in), or an animated GIF or APNG written by ugnis itself. Every output is
//! written to a temporary file beside the target and renamed over it only when complete, so
//! a failed, interrupted or killed encode leaves no half video and never replaces an old one.

use std::io::{Read, Write};
use std::path::{Path, PathBuf};
use std::process::{Child, ChildStdin, Command, Stdio};

use image::RgbaImage;

use crate::io::atomic::{AtomicFile, WriterProcess};

/// Most frames per second a video may have.
pub const MAX_FPS: f64 = 1000.0;
/// Fewest frames per second a video may have (a frame every 100 seconds).
pub const MIN_FPS: f64 = 0.01;

/// What an output path asks for, by its extension.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum VideoKind {
    /// A video through ffmpeg, in this container (`mp4`, `webm`, `mkv`, `mov`).
    Ffmpeg(&'static str),
    /// Animated GIF (`.gif`), written by ugnis, looping forever; transparency is composed over
    /// the flame's background colour and delays are whole hundredths of a second.
    Gif,
    /// Animated PNG (`.apng`).
    Apng,
}

impl VideoKind {
    /// The kind of video a path names, or None (a folder of PNG frames, or another file).
    pub fn of(path: &Path) -> Option<VideoKind> {
        let ext = path.extension()?.to_string_lossy().to_ascii_lowercase();
        Some(match ext.as_str() {
            "mp4" => VideoKind::Ffmpeg("mp4"),
            "webm" => VideoKind::Ffmpeg("webm"),
            "mkv" => VideoKind::Ffmpeg("matroska"),
            "mov" => VideoKind::Ffmpeg("mov"),
            "gif" => VideoKind::Gif,
            "apng" => VideoKind::Apng,
            _ => return None,
        })
    }
}

/// Why a video could not be written.
#[derive(Debug, thiserror::Error)]
pub enum VideoError {
    /// The output needs ffmpeg and the program could not be run; `what` names the output
    /// ("a .mp4 video").
    #[error(
        "'{path}': writing {what} needs ffmpeg, which is not on PATH (Debian and Ubuntu: \
         apt install ffmpeg; Fedora: dnf install ffmpeg; macOS: brew install ffmpeg)"
    )]
    FfmpegMissing {
        /// The video that was to be written.
        path: PathBuf,
        /// What needed ffmpeg, for the message ("a .mp4 video").
        what: String,
    },
    /// ffmpeg ended with an error or stopped reading frames; the message ends with the last
    /// lines ffmpeg wrote to its standard error.
    #[error("'{path}': ffmpeg failed ({status}){}", tail(.stderr))]
    FfmpegFailed {
        /// The video that was being written.
        path: PathBuf,
        /// ffmpeg's exit status, as the system words it ("exit status: 1").
        status: String,
        /// Everything ffmpeg wrote to its standard error.
        stderr: String,
    },
    /// Creating, writing or renaming the file (or starting ffmpeg) failed.
    #[error("'{path}': {source}")]
    Io {
        /// The video that was being written.
        path: PathBuf,
        /// The system's error.
        source: std::io::Error,
    },
    /// The output cannot be made as asked (not a video name, a frame rate out of range, a frame
    /// of the wrong size) or the GIF/APNG encoder failed.
    #[error("'{path}': {message}")]
    Encode {
        /// The video that was being written.
        path: PathBuf,
        /// What went wrong.
        message: String,
    },
}

fn tail(stderr: &str) -> String {
    let lines: Vec<&str> = stderr.lines().filter(|l| !l.trim().is_empty()).collect();
    if lines.is_empty() {
        String::new()
    } else {
        format!(": {}", lines[lines.len().saturating_sub(3)..].join(" / "))
    }
}

/// Settings of a video.
#[derive(Clone, Debug)]
pub struct VideoOptions {
    /// Frames per second, from [`MIN_FPS`] to [`MAX_FPS`] (default 25; a GIF rounds the
    /// delay to hundredths of a second).
    pub fps: f64,
    /// A sound file to mux in (ffmpeg outputs only); the video ends with the shorter of the two.
    pub audio: Option<PathBuf>,
    /// Where in the sound the video starts (seconds), for a video of frames from the middle of
    /// an animation.
    pub audio_start: f64,
    /// ffmpeg's constant-quality factor (lower is better; 18 is visually lossless for H.264).
    pub crf: u32,
    /// The ffmpeg program (default: `ffmpeg` on PATH).
    pub ffmpeg: PathBuf,
}

impl Default for VideoOptions {
    fn default() -> Self {
        VideoOptions {
            fps: 25.0,
            audio: None,
            audio_start: 0.0,
            crf: 18,
            ffmpeg: PathBuf::from("ffmpeg"),
        }
    }
}

/// Is ffmpeg runnable?
pub fn ffmpeg_available(ffmpeg: &Path) -> bool {
    Command::new(ffmpeg)
        .arg("-version")
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .status()
        .is_ok_and(|s| s.success())
}

/// A video being written, frame by frame.
pub struct Video {
    path: PathBuf,
    width: u32,
    height: u32,
    /// None once the encoder has failed.
    sink: Option<Sink>,
}

enum Sink {
    Ffmpeg {
        child: Child,
        stdin: Option<ChildStdin>,
        stderr: std::thread::JoinHandle<String>,
        tmp: AtomicFile,
        /// ffmpeg writes the temporary file by name: registered, so that a program ending on
        /// a signal stops it before removing the file.
        writer: WriterProcess,
    },
    Gif {
        enc: Box<image::codecs::gif::GifEncoder<std::fs::File>>,
        tmp: AtomicFile,
        delay: image::Delay,
    },
    Apng {
        writer: Box<png::Writer<std::fs::File>>,
        tmp: AtomicFile,
    },
}

impl Video {
    /// Start a video of `frames` frames of `width`×`height` at `path` (its kind by the
    /// extension, see [`VideoKind::of`]).
    pub fn create(
        path: &Path,
        width: u32,
        height: u32,
        frames: u32,
        opts: &VideoOptions,
    ) -> Result<Video, VideoError> {
        let io = |source| VideoError::Io {
            path: path.to_path_buf(),
            source,
        };
        let kind = VideoKind::of(path).ok_or_else(|| VideoError::Encode {
            path: path.to_path_buf(),
            message: "not a video name (expected .mp4, .webm, .mkv, .mov, .gif or .apng)".into(),
        })?;
        if !(MIN_FPS..=MAX_FPS).contains(&opts.fps) {
            return Err(VideoError::Encode {
                path: path.to_path_buf(),
                message: format!(
                    "{} frames per second; the range is {MIN_FPS}–{MAX_FPS}",
                    opts.fps
                ),
            });
        }
        let mut tmp = AtomicFile::create(path).map_err(io)?;
        let sink = match kind {
            VideoKind::Ffmpeg(format) => {
                if !ffmpeg_available(&opts.ffmpeg) {
                    return Err(VideoError::FfmpegMissing {
                        path: path.to_path_buf(),
                        what: format!(
                            "a .{} video",
                            path.extension().unwrap_or_default().to_string_lossy()
                        ),
                    });
                }
                let mut child = ffmpeg_command(tmp.temp_path(), format, width, height, opts)
                    .spawn()
                    .map_err(io)?;
                let stdin = child.stdin.take();
                let mut err = child.stderr.take().expect("stderr is piped");
                let stderr = std::thread::spawn(move || {
                    let mut s = String::new();
                    let _ = err.read_to_string(&mut s);
                    s
                });
                Sink::Ffmpeg {
                    writer: WriterProcess::register(child.id()),
                    child,
                    stdin,
                    stderr,
                    tmp,
                }
            }
            VideoKind::Gif => {
                let file = tmp.file().try_clone().map_err(io)?;
                let mut enc = image::codecs::gif::GifEncoder::new_with_speed(file, 10);
                enc.set_repeat(image::codecs::gif::Repeat::Infinite)
                    .map_err(|e| encode_error(path, e))?;
                // GIF delays are whole hundredths of a second.
                let cs = (100.0 / opts.fps).round().max(1.0) as u32;
                Sink::Gif {
                    enc: Box::new(enc),
                    tmp,
                    delay: image::Delay::from_numer_denom_ms(cs * 10, 1),
                }
            }
            VideoKind::Apng => {
                let file = tmp.file().try_clone().map_err(io)?;
                let mut enc = png::Encoder::new(file, width, height);
                enc.set_color(png::ColorType::Rgba);
                enc.set_depth(png::BitDepth::Eight);
                let png_err = |e: png::EncodingError| encode_error(path, e);
                enc.set_animated(frames.max(1), 0).map_err(png_err)?;
                let (num, den) = frame_delay(opts.fps);
                enc.set_frame_delay(num, den).map_err(png_err)?;
                let writer = enc.write_header().map_err(png_err)?;
                Sink::Apng {
                    writer: Box::new(writer),
                    tmp,
                }
            }
        };
        Ok(Video {
            path: path.to_path_buf(),
            width,
            height,
            sink: Some(sink),
        })
    }

    /// Add the next frame (of the size the video was created with). Where the frame is
    /// transparent, a GIF or ffmpeg video shows it over `background` (the flame's background
    /// colour, 8-bit RGB); an APNG keeps the alpha.
    pub fn push(&mut self, frame: &RgbaImage, background: [u8; 3]) -> Result<(), VideoError> {
        if frame.dimensions() != (self.width, self.height) {
            return Err(VideoError::Encode {
                path: self.path.clone(),
                message: format!(
                    "a frame of {}x{} in a video of {}x{}",
                    frame.width(),
                    frame.height(),
                    self.width,
                    self.height
                ),
            });
        }
        let failed = || VideoError::Encode {
            path: self.path.clone(),
            message: "the encoder has already failed".into(),
        };
        match self.sink.as_mut().ok_or_else(failed)? {
            Sink::Ffmpeg { stdin, .. } => {
                let rgb = over(frame, background);
                let w = stdin.as_mut().expect("open until finish");
                if let Err(e) = w.write_all(&rgb) {
                    // ffmpeg has ended: report what it said.
                    return Err(self.ffmpeg_ended(e));
                }
                Ok(())
            }
            Sink::Gif { enc, delay, .. } => {
                let rgba = over(frame, background)
                    .chunks_exact(3)
                    .flat_map(|p| [p[0], p[1], p[2], 255])
                    .collect();
                let f = RgbaImage::from_raw(self.width, self.height, rgba)
                    .expect("the size was checked");
                enc.encode_frame(image::Frame::from_parts(f, 0, 0, *delay))
                    .map_err(|e| encode_error(&self.path, e))
            }
            Sink::Apng { writer, .. } => writer
                .write_image_data(frame.as_raw())
                .map_err(|e| encode_error(&self.path, e)),
        }
    }

    fn ffmpeg_ended(&mut self, e: std::io::Error) -> VideoError {
        let path = self.path.clone();
        if let Some(Sink::Ffmpeg {
            mut child,
            stdin,
            stderr,
            ..
        }) = self.sink.take()
        {
            drop(stdin);
            let status = child.wait().map(|s| s.to_string()).unwrap_or(e.to_string());
            let stderr = stderr.join().unwrap_or_default();
            return VideoError::FfmpegFailed {
                path,
                status,
                stderr,
            };
        }
        VideoError::Io { path, source: e }
    }

    /// End the video and put it in place.
    pub fn finish(self) -> Result<(), VideoError> {
        let path = self.path;
        let io = |source| VideoError::Io {
            path: path.clone(),
            source,
        };
        let Some(sink) = self.sink else {
            return Err(VideoError::Encode {
                path,
                message: "the encoder has already failed".into(),
            });
        };
        match sink {
            Sink::Ffmpeg {
                mut child,
                stdin,
                stderr,
                tmp,
                writer,
            } => {
                drop(stdin);
                let status = child.wait().map_err(io)?;
                drop(writer);
                let stderr = stderr.join().unwrap_or_default();
                if !status.success() {
                    return Err(VideoError::FfmpegFailed {
                        path: path.clone(),
                        status: status.to_string(),
                        stderr,
                    });
                }
                tmp.commit().map_err(io)
            }
            Sink::Gif { enc, tmp, .. } => {
                drop(enc);
                tmp.commit().map_err(io)
            }
            Sink::Apng { writer, tmp } => {
                writer.finish().map_err(|e| encode_error(&path, e))?;
                tmp.commit().map_err(io)
            }
        }
    }
}

fn encode_error(path: &Path, e: impl std::fmt::Display) -> VideoError {
    VideoError::Encode {
        path: path.to_path_buf(),
        message: e.to_string(),
    }
}

/// The frame delay 1/fps as a fraction of 16-bit numbers.
fn frame_delay(fps: f64) -> (u16, u16) {
    let den = (fps * 100.0).round().clamp(1.0, 65535.0) as u16;
    (100, den.max(1))
}

/// RGB bytes of a frame (colours not premultiplied) composed over `background`.
fn over(frame: &RgbaImage, background: [u8; 3]) -> Vec<u8> {
    let mut out = Vec::with_capacity(frame.as_raw().len() / 4 * 3);
    for p in frame.pixels() {
        let a = p[3] as u32;
        for c in 0..3 {
            let v = p[c] as u32 * a + background[c] as u32 * (255 - a);
            out.push(((v + 127) / 255) as u8);
        }
    }
    out
}

/// ffmpeg reading raw RGB frames from its standard input and writing `format` to `out`.
fn ffmpeg_command(
    out: &Path,
    format: &str,
    width: u32,
    height: u32,
    opts: &VideoOptions,
) -> Command {
    let mut c = Command::new(&opts.ffmpeg);
    c.args(["-hide_banner", "-loglevel", "error", "-y"])
        .args(["-f", "rawvideo", "-pix_fmt", "rgb24"])
        .args(["-s", &format!("{width}x{height}")])
        .args(["-framerate", &format!("{}", opts.fps)])
        .args(["-i", "-"]);
    if let Some(a) = &opts.audio {
        if opts.audio_start > 0.0 {
            c.args(["-ss", &format!("{}", opts.audio_start)]);
        }
        c.arg("-i").arg(a);
        c.args(["-map", "0:v", "-map", "1:a", "-shortest"]);
        let codec = if format == "webm" { "libopus" } else { "aac" };
        c.args(["-c:a", codec, "-b:a", "192k"]);
    }
    // 4:2:0 video needs even sizes: pad the odd row or column.
    c.args(["-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2"]);
    let crf = opts.crf.to_string();
    if format == "webm" {
        c.args(["-c:v", "libvpx-vp9", "-b:v", "0", "-crf", &crf]);
    } else {
        c.args(["-c:v", "libx264", "-preset", "medium", "-crf", &crf]);
    }
    c.args(["-pix_fmt", "yuv420p"]);
    if format == "mp4" || format == "mov" {
        c.args(["-movflags", "+faststart"]);
    }
    c.args(["-f", format]).arg(out);
    c.stdin(Stdio::piped())
        .stdout(Stdio::null())
        .stderr(Stdio::piped());
    c
}

#[cfg(test)]
mod tests {
    use super::*;

    fn scratch(tag: &str) -> PathBuf {
        let d = std::env::temp_dir().join(format!("ugnis-video-{tag}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&d);
        std::fs::create_dir_all(&d).unwrap();
        d
    }

    fn frame(k: u32) -> RgbaImage {
        RgbaImage::from_fn(33, 21, |x, y| {
            image::Rgba([(x * 7 + k * 40) as u8, (y * 11) as u8, 90, 255])
        })
    }

    #[test]
    fn kinds_by_extension() {
        assert_eq!(
            VideoKind::of(Path::new("a.MP4")),
            Some(VideoKind::Ffmpeg("mp4"))
        );
        assert_eq!(
            VideoKind::of(Path::new("a.mkv")),
            Some(VideoKind::Ffmpeg("matroska"))
        );
        assert_eq!(VideoKind::of(Path::new("a.gif")), Some(VideoKind::Gif));
        assert_eq!(VideoKind::of(Path::new("a.apng")), Some(VideoKind::Apng));
        assert_eq!(VideoKind::of(Path::new("frames")), None);
        assert_eq!(VideoKind::of(Path::new("a.png")), None);
    }

    #[test]
    fn apng_and_gif_hold_every_frame() {
        let d = scratch("builtin");
        for name in ["a.apng", "a.gif"] {
            let p = d.join(name);
            let opts = VideoOptions {
                fps: 10.0,
                ..VideoOptions::default()
            };
            let mut v = Video::create(&p, 33, 21, 3, &opts).unwrap();
            for k in 0..3 {
                v.push(&frame(k), [0; 3]).unwrap();
            }
            assert!(
                v.push(&RgbaImage::new(2, 2), [0; 3]).is_err(),
                "a frame of another size"
            );
            v.finish().unwrap();
            let bytes = std::fs::read(&p).unwrap();
            if name.ends_with("apng") {
                let dec = png::Decoder::new(std::io::Cursor::new(bytes));
                let r = dec.read_info().unwrap();
                let ac = r.info().animation_control.unwrap();
                assert_eq!(ac.num_frames, 3);
            } else {
                use image::AnimationDecoder;
                let dec = image::codecs::gif::GifDecoder::new(std::io::Cursor::new(bytes)).unwrap();
                let frames = dec.into_frames().collect_frames().unwrap();
                assert_eq!(frames.len(), 3);
                assert_eq!(frames[1].delay().numer_denom_ms(), (100, 1));
            }
        }
        // Only the finished files remain.
        assert_eq!(std::fs::read_dir(&d).unwrap().count(), 2);
    }

    #[test]
    fn without_ffmpeg_the_message_names_the_package_and_nothing_is_left() {
        let d = scratch("noffmpeg");
        let opts = VideoOptions {
            ffmpeg: d.join("no-such-ffmpeg"),
            ..VideoOptions::default()
        };
        let e = Video::create(&d.join("m.mp4"), 32, 20, 2, &opts)
            .err()
            .unwrap();
        let msg = e.to_string();
        assert!(
            msg.contains("apt install ffmpeg") && msg.contains("m.mp4"),
            "{msg}"
        );
        assert_eq!(std::fs::read_dir(&d).unwrap().count(), 0);
        let e = Video::create(
            &d.join("m.gif"),
            32,
            20,
            2,
            &VideoOptions {
                fps: 0.0,
                ..VideoOptions::default()
            },
        );
        assert!(e.is_err());
    }

    #[test]
    fn ffmpeg_writes_an_mp4_with_every_frame() {
        let opts = VideoOptions::default();
        assert!(
            ffmpeg_available(&opts.ffmpeg),
            "ffmpeg must be installed for this test (.ci/run installs it)"
        );
        let d = scratch("mp4");
        let p = d.join("m.mp4");
        let mut v = Video::create(&p, 33, 21, 5, &opts).unwrap();
        for k in 0..5 {
            v.push(&frame(k), [0; 3]).unwrap();
        }
        v.finish().unwrap();
        let out = Command::new("ffprobe")
            .args(["-v", "error", "-count_frames", "-select_streams", "v:0"])
            .args([
                "-show_entries",
                "stream=nb_read_frames,width,height",
                "-of",
                "csv=p=0",
            ])
            .arg(&p)
            .output()
            .unwrap();
        let s = String::from_utf8_lossy(&out.stdout);
        // Padded to even sizes.
        assert_eq!(s.trim(), "34,22,5", "{s}");
        assert_eq!(std::fs::read_dir(&d).unwrap().count(), 1);
    }

    #[test]
    fn a_killed_ffmpeg_is_an_error_and_leaves_no_file() {
        // A stand-in "ffmpeg" that answers -version and then dies at once.
        let d = scratch("killed");
        let fake = d.join("ffmpeg");
        std::fs::write(
            &fake,
            "#!/bin/sh\n[ \"$1\" = -version ] && exit 0\necho 'simulated crash' >&2\nexit 3\n",
        )
        .unwrap();
        use std::os::unix::fs::PermissionsExt;
        std::fs::set_permissions(&fake, std::fs::Permissions::from_mode(0o755)).unwrap();
        let opts = VideoOptions {
            ffmpeg: fake,
            ..VideoOptions::default()
        };
        let p = d.join("m.webm");
        let mut v = Video::create(&p, 320, 200, 50, &opts).unwrap();
        let big = RgbaImage::new(320, 200);
        let mut failed = None;
        for _ in 0..50 {
            if let Err(e) = v.push(&big, [0; 3]) {
                failed = Some(e);
                break;
            }
        }
        let e = match failed {
            Some(e) => e,
            None => v.finish().expect_err("ffmpeg exited with 3"),
        };
        assert!(e.to_string().contains("ffmpeg failed"), "{e}");
        assert!(!p.exists());
        assert_eq!(
            std::fs::read_dir(&d).unwrap().count(),
            1,
            "only the stand-in remains"
        );
    }
}
