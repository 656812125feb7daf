//! The one-line error report: the error and its causes joined by `: `, each cause once (a
//! library error whose text already holds its source's text is not followed by it again).

/// `error` and its chain of sources on one line, skipping a source whose text the line
/// already ends with or contains.
pub fn one_line(error: &anyhow::Error) -> String {
    let mut line = String::new();
    for cause in error.chain() {
        let text = cause.to_string().replace('\n', " ");
        if text.is_empty() || line.contains(&text) {
            continue;
        }
        if !line.is_empty() {
            line.push_str(": ");
        }
        line.push_str(&text);
    }
    line
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A library error that prints its source and also returns it (as `#[error("{path}:
    /// {source}")]` with a `source` field does).
    #[derive(Debug)]
    struct WithSource(std::io::Error);

    impl std::fmt::Display for WithSource {
        fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
            write!(f, "a.toml: {}", self.0)
        }
    }

    impl std::error::Error for WithSource {
        fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
            Some(&self.0)
        }
    }

    #[test]
    fn doubled_error_source_prints_once() {
        let e = anyhow::Error::new(WithSource(std::io::Error::from_raw_os_error(21)))
            .context("reading the scene");
        assert_eq!(
            one_line(&e),
            "reading the scene: a.toml: Is a directory (os error 21)"
        );
    }
}
