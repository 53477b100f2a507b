//! Writing outputs safely, for every crate and command that writes a file.
//!
//! * [`write_atomic`] and [`AtomicFile`] write to a temporary file in the
//!   destination's directory and rename it over the destination only when
//!   everything was written, so a failed or interrupted run never leaves a
//!   half-written file and never destroys an existing one.
//! * [`same_file`] and [`check_outputs`] refuse an output path that names an
//!   input (after resolving `.`/`..`, symbolic and hard links) or another
//!   output, before any work is done.

use std::fs::File;
use std::io::{self, BufWriter, Write};
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicU64, Ordering};
use thiserror::Error;

/// An output path that would overwrite an input or another output.
#[derive(Debug, Error, PartialEq, Eq)]
pub enum CollisionError {
    /// The output names the same file as an input.
    #[error("{output}: this output is the input {input}; refusing to overwrite an input, choose another output path")]
    OverwritesInput { output: PathBuf, input: PathBuf },
    /// Two outputs name the same file.
    #[error(
        "{output}: given as two outputs ({first} and {second}); choose a different path for each"
    )]
    TwoOutputs {
        output: PathBuf,
        first: String,
        second: String,
    },
}

/// `path` with `.` and `..` resolved and links followed, also when the file
/// itself does not exist yet (its directory is resolved instead).
fn resolve(path: &Path) -> PathBuf {
    if let Ok(p) = path.canonicalize() {
        return p;
    }
    let parent = match path.parent() {
        Some(p) if !p.as_os_str().is_empty() => p.to_path_buf(),
        _ => PathBuf::from("."),
    };
    match (parent.canonicalize(), path.file_name()) {
        (Ok(dir), Some(name)) => dir.join(name),
        _ => path.to_path_buf(),
    }
}

/// Whether `a` and `b` name the same file: the same resolved path, or (on
/// Unix) the same device and inode, which also catches hard links.
pub fn same_file(a: &Path, b: &Path) -> bool {
    if resolve(a) == resolve(b) {
        return true;
    }
    #[cfg(unix)]
    {
        use std::os::unix::fs::MetadataExt;
        if let (Ok(ma), Ok(mb)) = (std::fs::metadata(a), std::fs::metadata(b)) {
            return ma.dev() == mb.dev() && ma.ino() == mb.ino();
        }
    }
    false
}

/// Refuse outputs that name an input or each other. `outputs` pairs each path
/// with the option that gave it (e.g. `"--png"`), for the message.
pub fn check_outputs<'a>(
    inputs: impl IntoIterator<Item = &'a Path>,
    outputs: &[(&str, &Path)],
) -> Result<(), CollisionError> {
    let inputs: Vec<&Path> = inputs.into_iter().collect();
    for (i, (what, out)) in outputs.iter().enumerate() {
        if let Some(input) = inputs.iter().find(|inp| same_file(inp, out)) {
            return Err(CollisionError::OverwritesInput {
                output: out.to_path_buf(),
                input: input.to_path_buf(),
            });
        }
        if let Some((first, _)) = outputs[..i].iter().find(|(_, o)| same_file(o, out)) {
            return Err(CollisionError::TwoOutputs {
                output: out.to_path_buf(),
                first: first.to_string(),
                second: what.to_string(),
            });
        }
    }
    Ok(())
}

static COUNTER: AtomicU64 = AtomicU64::new(0);

/// A hidden temporary name beside `dest`, unique within and across processes.
fn temp_path(dest: &Path) -> PathBuf {
    let name = dest
        .file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_else(|| "out".into());
    let n = COUNTER.fetch_add(1, Ordering::Relaxed);
    dest.with_file_name(format!(".{name}.tmp-{}-{n}", std::process::id()))
}

/// A file being written: writes go to a temporary file beside the
/// destination; [`AtomicFile::commit`] flushes it and renames it over the
/// destination. Dropped without `commit` (an error, a panic), the temporary
/// file is removed and the destination is untouched.
pub struct AtomicFile {
    dest: PathBuf,
    tmp: PathBuf,
    file: Option<BufWriter<File>>,
}

impl AtomicFile {
    /// Start writing `dest`. Fails like `File::create` on the directory.
    pub fn create(dest: &Path) -> io::Result<Self> {
        let tmp = temp_path(dest);
        let file = File::create(&tmp)?;
        Ok(AtomicFile {
            dest: dest.to_path_buf(),
            tmp,
            file: Some(BufWriter::new(file)),
        })
    }

    /// Flush everything to disk and move the file into place.
    pub fn commit(mut self) -> io::Result<()> {
        let Some(w) = self.file.take() else {
            return Ok(());
        };
        let file = w.into_inner().map_err(io::IntoInnerError::into_error)?;
        file.sync_all()?;
        drop(file);
        std::fs::rename(&self.tmp, &self.dest)
    }
}

impl Write for AtomicFile {
    fn write(&mut self, buf: &[u8]) -> io::Result<usize> {
        match &mut self.file {
            Some(f) => f.write(buf),
            None => Err(io::Error::other("file already committed")),
        }
    }

    fn flush(&mut self) -> io::Result<()> {
        match &mut self.file {
            Some(f) => f.flush(),
            None => Ok(()),
        }
    }
}

impl Drop for AtomicFile {
    fn drop(&mut self) {
        if self.file.take().is_some() {
            let _ = std::fs::remove_file(&self.tmp);
        }
    }
}

/// Write `bytes` to `path` through a temporary file and a rename.
pub fn write_atomic(path: &Path, bytes: &[u8]) -> io::Result<()> {
    let mut f = AtomicFile::create(path)?;
    f.write_all(bytes)?;
    f.commit()
}

#[cfg(test)]
mod tests {
    use super::*;

    use fcc_testkit::tmpdir;

    fn entries(d: &Path) -> Vec<String> {
        let mut v: Vec<String> = std::fs::read_dir(d)
            .unwrap()
            .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
            .collect();
        v.sort();
        v
    }

    #[test]
    fn output_spelled_differently_from_the_input_is_the_same_file() {
        let d = tmpdir("spelled");
        let input = d.join("a.npy");
        std::fs::write(&input, b"x").unwrap();
        let sub = d.join("sub");
        std::fs::create_dir_all(&sub).unwrap();
        let dotted = sub.join("..").join(".").join("a.npy");
        assert!(same_file(&input, &dotted));
        let err = check_outputs([input.as_path()], &[("--output", dotted.as_path())]).unwrap_err();
        assert!(
            matches!(err, CollisionError::OverwritesInput { .. }),
            "{err}"
        );
        assert!(err.to_string().contains("refusing to overwrite an input"));
        assert!(check_outputs([input.as_path()], &[("--output", &d.join("b.npy"))]).is_ok());
    }

    #[cfg(unix)]
    #[test]
    fn output_through_a_symlink_or_hard_link_is_the_input() {
        let d = tmpdir("links");
        let input = d.join("a.bin");
        std::fs::write(&input, b"x").unwrap();
        std::os::unix::fs::symlink(&input, d.join("sym.bin")).unwrap();
        std::fs::hard_link(&input, d.join("hard.bin")).unwrap();
        assert!(same_file(&input, &d.join("sym.bin")));
        assert!(same_file(&input, &d.join("hard.bin")));
        assert!(!same_file(&input, &d.join("other.bin")));
    }

    #[test]
    fn two_outputs_on_one_path_are_refused() {
        let d = tmpdir("two");
        let p = d.join("out.png");
        let err = check_outputs([], &[("--png", p.as_path()), ("--ply", p.as_path())]).unwrap_err();
        assert_eq!(
            err,
            CollisionError::TwoOutputs {
                output: p.clone(),
                first: "--png".into(),
                second: "--ply".into()
            }
        );
    }

    #[test]
    fn atomic_write_replaces_and_leaves_no_temporary_file() {
        let d = tmpdir("replace");
        let p = d.join("out.txt");
        std::fs::write(&p, b"old").unwrap();
        write_atomic(&p, b"new").unwrap();
        assert_eq!(std::fs::read(&p).unwrap(), b"new");
        assert_eq!(entries(&d), ["out.txt"]);
    }

    #[test]
    fn interrupted_write_keeps_the_old_file_and_removes_the_temporary() {
        let d = tmpdir("interrupted");
        let p = d.join("out.txt");
        std::fs::write(&p, b"old").unwrap();
        {
            let mut f = AtomicFile::create(&p).unwrap();
            f.write_all(b"half of the new cont").unwrap();
            // Dropped without commit, as when an error ends the run.
        }
        assert_eq!(std::fs::read(&p).unwrap(), b"old");
        assert_eq!(entries(&d), ["out.txt"]);
    }

    #[test]
    fn write_into_a_missing_directory_fails_without_creating_anything() {
        let d = tmpdir("missing");
        let p = d.join("no-such-dir").join("out.txt");
        assert!(write_atomic(&p, b"x").is_err());
        assert!(entries(&d).is_empty());
    }
}
