//! [`FieldPath`]: a scene field by its path, `fingertip[0].material.youngs_modulus`,
//! `body[1].shape[0].density`, `gripper.squeeze.depth`: the same paths the scene's own errors
//! name ([`SceneError::field`](softgrip_scene::SceneError::field)), set in the scene's TOML
//! tree before the scene is parsed and checked. An entry of an array of tables is picked by its
//! position (`controller[0]`) or by its `name` (`controller[grasp].force`,
//! `robot[gripper].initial.finger_joint`).

use std::fmt;

/// Which entry of an array a path segment picks.
#[derive(Debug, Clone, PartialEq, Eq)]
enum Index {
    /// By position, from 0.
    At(usize),
    /// The table whose `name` is this.
    Named(String),
}

/// One step of a path: a key, optionally followed by an index into the array it names.
#[derive(Debug, Clone, PartialEq, Eq)]
struct Segment {
    key: String,
    index: Option<Index>,
}

/// Whether `s` is a key or a name: letters, digits, `_` or `-`, not empty.
fn is_word(s: &str) -> bool {
    !s.is_empty()
        && s.chars()
            .all(|c| c.is_ascii_alphanumeric() || c == '_' || c == '-')
}

/// A checked field path: keys separated by `.`, each key optionally indexed (`body[1]`).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct FieldPath {
    text: String,
    segments: Vec<Segment>,
}

impl FieldPath {
    /// Parses `text`; the message says what is wrong.
    pub fn parse(text: &str) -> Result<Self, String> {
        if text.is_empty() {
            return Err("is empty".to_string());
        }
        let mut segments = Vec::new();
        for part in text.split('.') {
            let (key, index) = match part.split_once('[') {
                None => (part, None),
                Some((key, rest)) => {
                    let inner = rest.strip_suffix(']').ok_or_else(|| {
                        format!(
                            "`{part}`: an index is written `key[N]` or `key[name]`, ending the segment"
                        )
                    })?;
                    let index = if inner.bytes().all(|b| b.is_ascii_digit()) && !inner.is_empty() {
                        Index::At(inner.parse().map_err(|_| {
                            format!("`{part}`: `{inner}` is not an index (0, 1, ...)")
                        })?)
                    } else if is_word(inner) {
                        Index::Named(inner.to_string())
                    } else {
                        return Err(format!(
                            "`{part}`: `{inner}` is not an index (0, 1, ...) nor a name (letters, digits, `_` or `-`)"
                        ));
                    };
                    (key, Some(index))
                }
            };
            if !is_word(key) {
                return Err(format!(
                    "`{part}`: a key is letters, digits, `_` or `-` (no quotes, no spaces)"
                ));
            }
            segments.push(Segment {
                key: key.to_string(),
                index,
            });
        }
        Ok(Self {
            text: text.to_string(),
            segments,
        })
    }

    /// The path as written.
    pub fn as_str(&self) -> &str {
        &self.text
    }

    /// Sets the field to `value` in a scene's TOML tree. Every table and array on the way must
    /// exist in the tree (an index past an array's end is an error saying its length); the
    /// last key may be missing (a field left at its default) and is then added. The message
    /// says which part of the path is wrong.
    pub fn set(&self, root: &mut toml::Table, value: toml::Value) -> Result<(), String> {
        let mut table = root;
        let last = self.segments.len() - 1;
        for (k, seg) in self.segments.iter().enumerate() {
            let done = self.prefix(k);
            if k == last && seg.index.is_none() {
                table.insert(seg.key.clone(), value);
                return Ok(());
            }
            let entry = table.get_mut(&seg.key).ok_or_else(|| {
                format!("`{done}` is not in the base scene (only the last key may be missing)")
            })?;
            let entry = match &seg.index {
                None => entry,
                Some(index) => {
                    let toml::Value::Array(items) = entry else {
                        return Err(format!("`{}` is not an array", self.key_prefix(k)));
                    };
                    pick(items, index, &done, &self.key_prefix(k))?
                }
            };
            if k == last {
                *entry = value;
                return Ok(());
            }
            table = match entry {
                toml::Value::Table(t) => t,
                _ => return Err(format!("`{done}` is a value, not a table")),
            };
        }
        unreachable!("invariant: the loop returns at the last segment")
    }

    /// The path up to and including segment `k`.
    fn prefix(&self, k: usize) -> String {
        (self.segments[..=k].iter())
            .map(Segment::to_string)
            .collect::<Vec<_>>()
            .join(".")
    }

    /// The path up to segment `k`, with segment `k`'s key but without its index.
    fn key_prefix(&self, k: usize) -> String {
        let mut p = if k == 0 {
            String::new()
        } else {
            format!("{}.", self.prefix(k - 1))
        };
        p.push_str(&self.segments[k].key);
        p
    }
}

/// The entry of `items` (the array `array`) that `index` picks; `done` is the path so far.
fn pick<'a>(
    items: &'a mut [toml::Value],
    index: &Index,
    done: &str,
    array: &str,
) -> Result<&'a mut toml::Value, String> {
    let len = items.len();
    match index {
        Index::At(i) => items.get_mut(*i).ok_or_else(|| {
            format!("`{done}`: index {i} is past the end of `{array}`, which has {len} entries")
        }),
        Index::Named(name) => {
            fn name_of(v: &toml::Value) -> Option<&str> {
                v.get("name").and_then(toml::Value::as_str)
            }
            let names: Vec<String> = items
                .iter()
                .filter_map(|v| name_of(v).map(|n| format!("`{n}`")))
                .collect();
            let found = items.iter().position(|v| name_of(v) == Some(name.as_str()));
            match found {
                Some(i) => Ok(&mut items[i]),
                None if names.is_empty() => Err(format!(
                    "`{done}`: no entry of `{array}` is named `{name}` (its {len} entries have no names: pick one by its position, `{array}[0]`)"
                )),
                None => Err(format!(
                    "`{done}`: no entry of `{array}` is named `{name}` (names: {})",
                    names.join(", ")
                )),
            }
        }
    }
}

impl fmt::Display for Segment {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match &self.index {
            Some(Index::At(i)) => write!(f, "{}[{i}]", self.key),
            Some(Index::Named(n)) => write!(f, "{}[{n}]", self.key),
            None => write!(f, "{}", self.key),
        }
    }
}

impl fmt::Display for FieldPath {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.text)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn tree() -> toml::Table {
        toml::from_str(
            "[[body]]\nname = \"a\"\n[[body]]\nname = \"b\"\n[[body.shape]]\ndensity = 1.0\n\
             position = [1.0, 2.0, 3.0]\n[gripper.squeeze]\ndepth = 0.002\n",
        )
        .expect("test tree parses")
    }

    #[test]
    fn sets_nested_indexed_and_missing_last_keys() {
        let mut t = tree();
        let set = |t: &mut toml::Table, p: &str, v: f64| {
            FieldPath::parse(p)
                .expect("valid path")
                .set(t, toml::Value::Float(v))
        };
        set(&mut t, "body[1].shape[0].density", 5.0).expect("exists");
        set(&mut t, "body[1].shape[0].position[2]", 7.0).expect("exists");
        set(&mut t, "gripper.squeeze.depth", 0.003).expect("exists");
        set(&mut t, "gripper.squeeze.settle", 0.5).expect("a missing last key is added");
        set(&mut t, "body[b].shape[0].density", 6.0).expect("picked by name");
        let shape = &t["body"][1]["shape"][0];
        assert_eq!(shape["density"].as_float(), Some(6.0));
        assert_eq!(shape["position"][2].as_float(), Some(7.0));
        assert_eq!(t["gripper"]["squeeze"]["depth"].as_float(), Some(0.003));
        assert_eq!(t["gripper"]["squeeze"]["settle"].as_float(), Some(0.5));
    }

    #[test]
    fn wrong_paths_say_which_part() {
        let t = tree();
        let err = |p: &str| {
            FieldPath::parse(p)
                .and_then(|f| f.set(&mut t.clone(), toml::Value::Float(1.0)))
                .expect_err("a wrong path")
        };
        assert_eq!(
            err("body[2].name"),
            "`body[2]`: index 2 is past the end of `body`, which has 2 entries"
        );
        assert_eq!(
            err("fingertip[0].radius"),
            "`fingertip[0]` is not in the base scene (only the last key may be missing)"
        );
        assert_eq!(err("gripper[0].hold"), "`gripper` is not an array");
        assert_eq!(
            err("body[0].name.x"),
            "`body[0].name` is a value, not a table"
        );
        assert_eq!(
            err("body[x]"),
            "`body[x]`: no entry of `body` is named `x` (names: `a`, `b`)"
        );
        assert!(err("body[x y]").contains("nor a name"));
        assert!(err("body[]").contains("nor a name"));
        assert!(err("a..b").contains("a key is letters"));
    }
}
