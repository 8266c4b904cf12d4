//! ugnis: the desktop fractal editor (no arguments) and its command line.

#[macro_use]
mod cli;

use clap::{Parser, Subcommand};

#[derive(Parser, Debug)]
#[command(
    name = "ugnis",
    version,
    about = "Fractal flames, IFS, escape-time fractals and textured Bezier scenes"
)]
struct Cli {
    #[command(subcommand)]
    command: Option<Command>,
    /// File to open in the editor (when no subcommand is given)
    file: Option<std::path::PathBuf>,
    /// Progress on stderr: a bar on a terminal, a plain line every few seconds otherwise
    #[arg(long, value_enum, global = true, default_value_t = cli::ProgressMode::Auto)]
    progress: cli::ProgressMode,
}

#[derive(Subcommand, Debug)]
// Parsed once per run; boxing the larger argument sets would gain nothing.
#[allow(clippy::large_enum_variant)]
enum Command {
    /// Render a flame file to PNG or BMP
    Render(cli::render::RenderArgs),
    /// Sum saved render parts (`render --part I/N --save-state`) and develop the image
    Merge(cli::merge::MergeArgs),
    /// List what a flame, IFS, gradient or render state file holds
    Info(cli::info::InfoArgs),
    /// Convert between file formats (.ifs ↔ .fla/.flame, .png → .fla, .ugr ↔ .map ↔ .ggr, image → gradient)
    Convert(cli::convert::ConvertArgs),
    /// Generate a batch of random flames into one .fla, with thumbnails
    Random(cli::random::RandomArgs),
    /// Render an escape-time fractal (Mandelbrot, Julia, Newton, …) or a saved view
    Escape(cli::escape::EscapeArgs),
    /// Render a textured Bezier scene (.toml) to PNG or BMP
    Scene(cli::scene::SceneArgs),
    /// Render the frames of an animation (rotating triangles or in-betweens of flames)
    Animate(cli::animate::AnimateArgs),
    /// Draw an entry of a Fractint L-system file (.l) to SVG or PNG
    Lsystem(cli::lsystem::LsystemArgs),
    /// Estimate the fractal dimension of a flame, IFS or image by box counting
    Dimension(cli::dimension::DimensionArgs),
    /// Draw the Lorenz attractor (and show its sensitivity to the start)
    Lorenz(cli::lorenz::LorenzArgs),
    /// A small PNG of a flame, IFS, gradient or escape-time file, quickly (for file managers)
    Thumbnail(cli::thumbnail::ThumbnailArgs),
}

fn main() {
    cli::fit_allocator_to_address_limit();
    // Usage errors exit with status 1 and one message, like every other bad input; --help and
    // --version print to stdout and exit 0.
    let cli = match Cli::try_parse() {
        Ok(c) => c,
        Err(e) => {
            let code = if e.use_stderr() { 1 } else { 0 };
            let _ = e.print();
            std::process::exit(code);
        }
    };
    cli::set_progress_mode(cli.progress);
    // JWildfire's own resources (brushes, tiles, meshes), from the installation the user names.
    if let Some(Err(e)) = ugnis::io::jwf_install::install_from_env() {
        stderr!("warning: {e}; JWildfire's own resources are not available");
    }
    if cli.command.is_some() {
        cli::signals::install();
    }
    let result = match cli.command {
        Some(Command::Render(a)) => cli::render::run(a),
        Some(Command::Info(a)) => cli::info::run(a),
        Some(Command::Merge(a)) => cli::merge::run(a),
        Some(Command::Convert(a)) => cli::convert::run(a),
        Some(Command::Random(a)) => cli::random::run(a),
        Some(Command::Animate(a)) => cli::animate::run(a),
        Some(Command::Escape(a)) => cli::escape::run(a),
        Some(Command::Scene(a)) => cli::scene::run(a),
        Some(Command::Lsystem(a)) => cli::lsystem::run(a),
        Some(Command::Dimension(a)) => cli::dimension::run(a),
        Some(Command::Lorenz(a)) => cli::lorenz::run(a),
        Some(Command::Thumbnail(a)) => cli::thumbnail::run(a),
        None => run_gui(cli.file),
    };
    if let Err(e) = result {
        stderr!("error: {e:#}");
        std::process::exit(1);
    }
}

#[cfg(feature = "gui")]
fn run_gui(file: Option<std::path::PathBuf>) -> anyhow::Result<()> {
    ugnis::app::run(file).map_err(|e| anyhow::anyhow!("cannot start the window: {e}"))
}

#[cfg(not(feature = "gui"))]
fn run_gui(file: Option<std::path::PathBuf>) -> anyhow::Result<()> {
    match file {
        Some(f) => anyhow::bail!(
            "this build has no GUI (built without the 'gui' feature); read {} with `{}`",
            f.display(),
            cli::command_for(&f)
        ),
        None => anyhow::bail!(
            "this build has no GUI (built without the 'gui' feature); use a subcommand, see --help"
        ),
    }
}
