//! Output files: never over an input, never over an existing file without `--force`, never a
//! directory where a file is meant, and written whole: each output is a temporary file beside
//! its target ([`Output`]) that becomes the target only when everything is written, without
//! replacing a file that appeared meanwhile (a hard link never replaces; `--force` renames over
//! it, but never over an input).

use std::fs::File;
use std::path::{Path, PathBuf};

use anyhow::{Result, anyhow, bail};
pub use softgrip_scene::same_file;
use tempfile::NamedTempFile;

/// Checks that `out` may be written: it is not one of `inputs` (the same file under any name,
/// even with `force`), not a directory, and does not exist unless `force`.
pub fn check_output(out: &Path, inputs: &[&Path], force: bool) -> Result<()> {
    if let Some(input) = inputs.iter().find(|i| same_file(out, i)) {
        bail!(
            "{}: refusing to write the output over the input {}",
            out.display(),
            input.display()
        );
    }
    match std::fs::metadata(out) {
        Ok(m) if m.is_dir() => bail!(
            "{}: is a directory; give the name of a file to write",
            out.display()
        ),
        Ok(_) if !force => bail!("{}: exists; pass --force to overwrite it", out.display()),
        _ => Ok(()),
    }
}

/// An output being written: a temporary file in the target's folder, named after it
/// (`.NAME.XXXXXX.partial.EXT`, the target's extension kept for writers that read it), removed
/// if the command fails or is interrupted before [`commit`](Self::commit).
#[derive(Debug)]
pub struct Output {
    path: PathBuf,
    inputs: Vec<PathBuf>,
    force: bool,
    tmp: NamedTempFile,
}

impl Output {
    /// Checks `path` ([`check_output`]; an existing target must also be a regular file: the
    /// temporary file is renamed over it, which would replace a device such as `/dev/full`)
    /// and creates the temporary file beside it (so an unwritable folder is an error before
    /// any work is done).
    pub fn create(path: &Path, inputs: &[PathBuf], force: bool) -> Result<Self> {
        let refs: Vec<&Path> = inputs.iter().map(PathBuf::as_path).collect();
        check_output(path, &refs, force)?;
        if let Ok(meta) = std::fs::metadata(path)
            && !meta.is_file()
        {
            bail!(
                "{}: exists and is not a regular file (a device, FIFO or socket): give the path of a file to write",
                path.display()
            );
        }
        let dir = match path.parent() {
            Some(d) if !d.as_os_str().is_empty() => d,
            _ => Path::new("."),
        };
        let name = path
            .file_name()
            .map(|n| n.to_string_lossy().into_owned())
            .unwrap_or_default();
        let ext = path
            .extension()
            .map(|e| format!(".{}", e.to_string_lossy()))
            .unwrap_or_default();
        let tmp = tempfile::Builder::new()
            .prefix(&format!(".{name}."))
            .suffix(&format!(".partial{ext}"))
            .tempfile_in(dir)
            .map_err(|e| {
                anyhow!(
                    "{}: cannot create a file in {}: {}",
                    path.display(),
                    dir.display(),
                    os_error(&e)
                )
            })?;
        Ok(Self {
            path: path.to_path_buf(),
            inputs: inputs.to_vec(),
            force,
            tmp,
        })
    }

    /// The target.
    pub fn path(&self) -> &Path {
        &self.path
    }

    /// The temporary file's path (for writers that open the file by name).
    pub fn temp_path(&self) -> &Path {
        self.tmp.path()
    }

    /// The temporary file, to write the output into.
    pub fn file(&mut self) -> &mut File {
        self.tmp.as_file_mut()
    }

    /// Writes `bytes` into the temporary file.
    pub fn write_all(&mut self, bytes: &[u8]) -> Result<()> {
        use std::io::Write;
        self.tmp
            .write_all(bytes)
            .and_then(|()| self.tmp.flush())
            .map_err(|e| anyhow!("{}: {e}", self.path.display()))
    }

    /// Puts the written file at its target: without `--force` only if the target still does
    /// not exist (a file that appeared meanwhile is never replaced: the error says so and the
    /// temporary file is removed); with `--force` over it, unless it has become an input.
    pub fn commit(self) -> Result<()> {
        self.commit_or_keep(false).map(|_| ())
    }

    /// [`commit`](Self::commit), but when the target cannot be written the output is kept
    /// under its temporary name, which the error names (results that took long to compute
    /// are not thrown away).
    pub fn commit_or_keep(self, keep: bool) -> Result<PathBuf> {
        let Self {
            path,
            inputs,
            force,
            tmp,
        } = self;
        tmp.as_file()
            .sync_all()
            .map_err(|e| anyhow!("{}: {e}", path.display()))?;
        let kept = |tmp: NamedTempFile, why: String| -> anyhow::Error {
            if !keep {
                return anyhow!("{why}; nothing written");
            }
            // Beside the target, under a name of its own: NAME.kept-PID.EXT.
            let at = kept_name(&path);
            match tmp.persist_noclobber(&at) {
                Ok(_) => anyhow!("{why}; the output is kept in {}", at.display()),
                Err(e) => match e.file.keep() {
                    Ok((_, at)) => anyhow!("{why}; the output is kept in {}", at.display()),
                    Err(e) => anyhow!("{why}; the output is lost: {}", e.error),
                },
            }
        };
        if force
            && let Ok(meta) = std::fs::metadata(&path)
            && !meta.is_file()
        {
            let why = format!(
                "{}: became something other than a regular file while this process ran; not replaced",
                path.display()
            );
            return Err(kept(tmp, why));
        }
        if let Some(input) = inputs.iter().find(|i| same_file(&path, i)) {
            let why = format!(
                "{}: refusing to write the output over the input {}",
                path.display(),
                input.display()
            );
            return Err(kept(tmp, why));
        }
        let result = if force {
            tmp.persist(&path)
        } else {
            tmp.persist_noclobber(&path)
        };
        match result {
            Ok(_) => Ok(path),
            Err(e) if e.error.kind() == std::io::ErrorKind::AlreadyExists => {
                let why = format!(
                    "{}: created by another process while this one ran; not replaced (pass --force to overwrite)",
                    path.display()
                );
                Err(kept(e.file, why))
            }
            Err(e) => {
                let why = format!("{}: {}", path.display(), e.error);
                Err(kept(e.file, why))
            }
        }
    }
}

/// `NAME.kept-PID.EXT` beside `path` (`results.kept-4242.csv`): where an output that could not
/// be put in place is kept.
fn kept_name(path: &Path) -> PathBuf {
    let stem = path
        .file_stem()
        .map(|s| s.to_string_lossy().into_owned())
        .unwrap_or_default();
    let ext = path
        .extension()
        .map(|e| format!(".{}", e.to_string_lossy()))
        .unwrap_or_default();
    path.with_file_name(format!("{stem}.kept-{}{ext}", std::process::id()))
}

/// The OS error of `e` without the path tempfile appends to it (the message names the target).
fn os_error(e: &std::io::Error) -> String {
    if let Some(code) = e.raw_os_error() {
        return std::io::Error::from_raw_os_error(code).to_string();
    }
    // tempfile wraps the OS error as "<error> at path \"<temporary file>\"" and hides it.
    let text = e.to_string();
    match text.split_once(" at path \"") {
        Some((os, _)) => os.to_string(),
        None => text,
    }
}

/// Commits every output, or none: if one cannot be put in place, those already committed are
/// removed again and the others' temporary files are removed.
pub fn commit_all(outputs: Vec<Output>) -> Result<()> {
    let mut done: Vec<PathBuf> = Vec::new();
    for out in outputs {
        match out.commit_or_keep(false) {
            Ok(path) => done.push(path),
            Err(e) => {
                for p in &done {
                    std::fs::remove_file(p).ok();
                }
                return Err(e);
            }
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn refuses_input_existing_and_directories() {
        let dir = std::env::temp_dir().join(format!("softgrip-files-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap_or_default();
        let input = dir.join("in.toml");
        std::fs::write(&input, "x").unwrap_or_default();
        let other_name = dir.join(".").join("in.toml");
        let e = check_output(&other_name, &[&input], true).unwrap_err();
        assert!(e.to_string().contains("over the input"), "{e}");
        let out = dir.join("out.mcap");
        assert!(check_output(&out, &[&input], false).is_ok());
        std::fs::write(&out, "y").unwrap_or_default();
        let e = check_output(&out, &[&input], false).unwrap_err();
        assert!(e.to_string().contains("--force"), "{e}");
        assert!(check_output(&out, &[&input], true).is_ok());
        let e = check_output(&dir, &[&input], true).unwrap_err();
        assert!(e.to_string().contains("is a directory"), "{e}");
        std::fs::remove_dir_all(&dir).ok();
    }

    /// A file that appears at the target while the output is written is not replaced, and
    /// with `keep` the output survives under its temporary name.
    #[test]
    fn output_that_appears_meanwhile_is_not_replaced() {
        let dir = std::env::temp_dir().join(format!("softgrip-outputs-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap_or_default();
        let target = dir.join("r.csv");
        std::fs::remove_file(&target).ok();
        let mut out = Output::create(&target, &[], false).expect("creates");
        out.write_all(b"mine\n").expect("writes");
        std::fs::write(&target, "theirs\n").expect("the other process writes");
        let e = out
            .commit_or_keep(true)
            .expect_err("not replaced")
            .to_string();
        assert_eq!(
            std::fs::read_to_string(&target).ok().as_deref(),
            Some("theirs\n")
        );
        let kept = e.split("kept in ").nth(1).map(PathBuf::from).expect(&e);
        assert_eq!(
            std::fs::read_to_string(&kept).ok().as_deref(),
            Some("mine\n")
        );
        // commit_all: the second target exists, so neither is written.
        let a = dir.join("a.csv");
        std::fs::remove_file(&a).ok();
        let mut first = Output::create(&a, &[], false).expect("creates");
        first.write_all(b"a\n").expect("writes");
        let mut second = Output::create(&dir.join("b.csv"), &[], false).expect("creates");
        second.write_all(b"b\n").expect("writes");
        std::fs::write(dir.join("b.csv"), "other\n").expect("appears");
        assert!(commit_all(vec![first, second]).is_err());
        assert!(!a.exists(), "none written");
        let left = std::fs::read_dir(&dir).expect("lists").count();
        assert_eq!(
            left, 3,
            "r.csv, the kept output, b.csv: no temporary file left"
        );
        std::fs::remove_dir_all(&dir).ok();
    }
}
