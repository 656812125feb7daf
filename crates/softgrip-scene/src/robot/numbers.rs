//! Where a URDF's number is malformed: `urdf-rs` says "invalid float literal" or "Wrong vector
//! element count" without a line; this finds the first numeric attribute of a URDF element
//! that is not the numbers it should be, with its line, to add to that error.

/// The numeric attributes of URDF elements: (element, attribute, count of numbers).
const NUMERIC: [(&str, &str, usize); 20] = [
    ("origin", "xyz", 3),
    ("origin", "rpy", 3),
    ("axis", "xyz", 3),
    ("mass", "value", 1),
    ("inertia", "ixx", 1),
    ("inertia", "ixy", 1),
    ("inertia", "ixz", 1),
    ("inertia", "iyy", 1),
    ("inertia", "iyz", 1),
    ("inertia", "izz", 1),
    ("limit", "lower", 1),
    ("limit", "upper", 1),
    ("limit", "effort", 1),
    ("limit", "velocity", 1),
    ("box", "size", 3),
    ("cylinder", "radius", 1),
    ("cylinder", "length", 1),
    ("sphere", "radius", 1),
    ("mesh", "scale", 3),
    ("mimic", "multiplier", 1),
];

/// `line N: <element attribute="value">: expected K numbers`, for the first numeric attribute
/// of `text` that is not K numbers; `None` if all are.
pub(crate) fn first_bad_number(text: &str) -> Option<String> {
    let mut at = 0;
    while let Some(k) = text[at..].find('<') {
        let start = at + k + 1;
        let end = start + text[start..].find('>')?;
        at = end;
        let tag = &text[start..end];
        let name: String = tag
            .chars()
            .take_while(|c| !c.is_whitespace() && *c != '/')
            .collect();
        for (element, attr, count) in NUMERIC {
            if name != element {
                continue;
            }
            let Some(value) = attribute(tag, attr) else {
                continue;
            };
            let numbers: Vec<_> = value.split_whitespace().collect();
            if numbers.len() != count || numbers.iter().any(|n| n.parse::<f64>().is_err()) {
                let line = text[..start].matches('\n').count() + 1;
                let what = if count == 1 {
                    "a number".to_string()
                } else {
                    format!("{count} numbers")
                };
                return Some(format!(
                    "line {line}: <{element} {attr}=\"{value}\">: expected {what}"
                ));
            }
        }
    }
    None
}

/// The value of attribute `key` in the tag text `tag` (after its name), `"` or `'` quoted.
fn attribute<'a>(tag: &'a str, key: &str) -> Option<&'a str> {
    let mut from = 0;
    while let Some(k) = tag[from..].find(key) {
        let k = from + k;
        from = k + key.len();
        let before = tag[..k].chars().next_back();
        if !before.is_some_and(char::is_whitespace) {
            continue;
        }
        let rest = tag[from..].trim_start();
        let Some(rest) = rest.strip_prefix('=') else {
            continue;
        };
        let rest = rest.trim_start();
        let quote = rest.chars().next()?;
        if quote != '"' && quote != '\'' {
            return None;
        }
        let rest = &rest[1..];
        return Some(&rest[..rest.find(quote)?]);
    }
    None
}

#[cfg(test)]
mod tests {
    use super::first_bad_number;

    #[test]
    fn the_first_malformed_number_is_found_with_its_line() {
        let ok = "<robot>\n<link name=\"a\"><inertial><mass value=\"1\"/><origin xyz=\"0 0 1e-3\"/></inertial></link></robot>";
        assert_eq!(first_bad_number(ok), None);
        let bad = "<robot>\n<joint name=\"j\">\n  <limit effort=\"0\" lower=\"-1.57.\" upper=\"1\"/></joint></robot>";
        assert_eq!(
            first_bad_number(bad).as_deref(),
            Some("line 3: <limit lower=\"-1.57.\">: expected a number")
        );
        let short =
            "<robot><link name='a'><collision><origin rpy='0 0'/></collision></link></robot>";
        assert_eq!(
            first_bad_number(short).as_deref(),
            Some("line 1: <origin rpy=\"0 0\">: expected 3 numbers")
        );
    }
}
