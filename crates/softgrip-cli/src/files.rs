//! Output files: never over an input, never over an existing file without `--force`, never a
//! directory where a file is meant.

use std::path::Path;

use anyhow::{Result, bail};

/// Checks that `out` may be written: it is not one of `inputs` (the same file under any name,
/// even with `force`), not a directory, and does not exist unless `force`.
pub fn check_output(out: &Path, inputs: &[&Path], force: bool) -> Result<()> {
    for input in inputs {
        if same_file(out, input) {
            bail!(
                "{}: refusing to write the output over the input {}",
                out.display(),
                input.display()
            );
        }
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

/// Whether `a` and `b` name the same existing file (device and inode on Unix, canonical paths
/// elsewhere).
pub fn same_file(a: &Path, b: &Path) -> bool {
    #[cfg(unix)]
    {
        use std::os::unix::fs::MetadataExt;
        if let (Ok(x), Ok(y)) = (std::fs::metadata(a), std::fs::metadata(b)) {
            return x.dev() == y.dev() && x.ino() == y.ino();
        }
        false
    }
    #[cfg(not(unix))]
    {
        matches!((a.canonicalize(), b.canonicalize()), (Ok(x), Ok(y)) if x == y)
    }
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
}
