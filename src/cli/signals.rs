//! Signals that end a command: SIGINT (Ctrl+C), SIGTERM (`kill`, SLURM's `scancel`,
//! Kubernetes) and SIGHUP (the terminal closed) stop it at once, whatever it is doing —
//! iterating, estimating densities, tone mapping, encoding or saving.
//!
//! The signal handler only writes the signal's number into a pipe; a thread waiting on the
//! pipe then stops every save ([`ugnis::io::atomic::close`]: nothing is created or renamed
//! into place any more), stops the processes writing temporary files (ffmpeg), removes every
//! temporary file and exits with 128 + the signal's number (130, 143, 129), as shells report
//! a command ended by a signal. Old outputs are never touched: a save replaces its target
//! only by a rename, which the handler waits for or forbids.

use std::io::Write;

/// The exit status after signal `sig`: 128 + its number.
pub fn exit_status(sig: i32) -> i32 {
    128 + sig
}

/// The signal's name, for the message.
fn name(sig: i32) -> String {
    #[cfg(unix)]
    {
        match sig {
            libc::SIGINT => return "SIGINT".into(),
            libc::SIGTERM => return "SIGTERM".into(),
            libc::SIGHUP => return "SIGHUP".into(),
            _ => {}
        }
    }
    format!("signal {sig}")
}

/// Stop every save, remove the temporary files and exit (on the thread that saw the signal).
fn stop(sig: i32) -> ! {
    for pid in ugnis::io::atomic::close() {
        kill_and_reap(pid);
    }
    ugnis::io::atomic::remove_pending();
    let mut err = std::io::stderr().lock();
    // A progress bar may have left the cursor mid-line.
    let _ = writeln!(
        err,
        "\ninterrupted by {}: stopped; nothing unfinished was written",
        name(sig)
    );
    let _ = err.flush();
    std::process::exit(exit_status(sig))
}

#[cfg(unix)]
fn kill_and_reap(pid: u32) {
    let Ok(pid) = libc::pid_t::try_from(pid) else {
        return;
    };
    // SAFETY: plain system calls on a child process id; waitpid waits until the child is gone,
    // so it cannot create the temporary file again after it is removed.
    unsafe {
        if libc::kill(pid, libc::SIGKILL) == 0 {
            libc::waitpid(pid, std::ptr::null_mut(), 0);
        }
    }
}

#[cfg(not(unix))]
fn kill_and_reap(_pid: u32) {}

#[cfg(unix)]
mod unix {
    use std::io::Read;
    use std::os::fd::{AsRawFd, IntoRawFd};
    use std::os::unix::net::UnixStream;
    use std::sync::atomic::{AtomicI32, Ordering};

    /// The write end of the pipe the handler writes into.
    static PIPE: AtomicI32 = AtomicI32::new(-1);

    extern "C" fn on_signal(sig: libc::c_int) {
        let byte = sig as u8;
        let fd = PIPE.load(Ordering::Relaxed);
        // SAFETY: write(2) is async-signal-safe; errno is saved and restored around it.
        unsafe {
            let saved = *errno();
            libc::write(fd, (&byte as *const u8).cast(), 1);
            *errno() = saved;
        }
    }

    #[cfg(any(target_os = "linux", target_os = "android"))]
    unsafe fn errno() -> *mut libc::c_int {
        // SAFETY: the calling thread's errno.
        unsafe { libc::__errno_location() }
    }

    #[cfg(not(any(target_os = "linux", target_os = "android")))]
    unsafe fn errno() -> *mut libc::c_int {
        // SAFETY: the calling thread's errno.
        unsafe { libc::__error() }
    }

    pub fn install() {
        let Ok((mut reader, writer)) = UnixStream::pair() else {
            return;
        };
        // The handler must never block: a full pipe drops the byte (one is enough).
        if writer.set_nonblocking(true).is_err() {
            return;
        }
        PIPE.store(writer.as_raw_fd(), Ordering::Relaxed);
        // Kept open for the life of the process.
        let _ = writer.into_raw_fd();
        let spawned = std::thread::Builder::new()
            .name("signals".into())
            .spawn(move || {
                let mut b = [0u8; 1];
                loop {
                    match reader.read(&mut b) {
                        Ok(1) => super::stop(b[0] as i32),
                        Ok(_) => return,
                        Err(e) if e.kind() == std::io::ErrorKind::Interrupted => {}
                        Err(_) => return,
                    }
                }
            });
        if spawned.is_err() {
            return;
        }
        for sig in [libc::SIGINT, libc::SIGTERM, libc::SIGHUP] {
            // SAFETY: reads the current disposition, then installs a handler that only calls
            // write(2); the sigaction structs are fully initialised (zeroed, then set).
            unsafe {
                let mut old: libc::sigaction = std::mem::zeroed();
                libc::sigaction(sig, std::ptr::null(), &mut old);
                // A signal ignored by whoever started us stays ignored (`nohup` ignores
                // SIGHUP, a shell's background job SIGINT).
                if old.sa_sigaction == libc::SIG_IGN {
                    continue;
                }
                let mut sa: libc::sigaction = std::mem::zeroed();
                sa.sa_sigaction = on_signal as extern "C" fn(libc::c_int) as libc::sighandler_t;
                sa.sa_flags = libc::SA_RESTART;
                libc::sigemptyset(&mut sa.sa_mask);
                libc::sigaction(sig, &sa, std::ptr::null_mut());
            }
        }
    }
}

/// Install the handlers (for the commands, not the editor).
pub fn install() {
    #[cfg(unix)]
    unix::install();
    #[cfg(not(unix))]
    {
        // Ctrl+C (and the console closing) on other systems.
        let _ = ctrlc::set_handler(|| stop(2));
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn statuses_are_those_shells_report() {
        assert_eq!(exit_status(2), 130);
        assert_eq!(exit_status(15), 143);
        assert_eq!(exit_status(1), 129);
    }
}
