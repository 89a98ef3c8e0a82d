//! A scene's keys one at a time, by their dotted path (`camera.vfov_deg`,
//! `black_hole.0.spin`): read from the scene as TOML, and changed through
//! the same parsing and validation a file goes through, so a bad value is
//! refused with the message a file with it would get. For programs that
//! edit scenes (the Python package).

use super::Scene;
use crate::{Error, Result};

/// One step of a key path: a table's key, or an array's index.
enum Step<'p> {
    Key(&'p str),
    Index(usize),
}

fn steps(path: &str) -> Result<Vec<Step<'_>>> {
    if path.is_empty() || path.split('.').any(str::is_empty) {
        return Err(Error::Scene(format!(
            "`{path}` is not a scene key: write its table and name with dots, e.g. `camera.vfov_deg` or `black_hole.0.spin`"
        )));
    }
    Ok(path
        .split('.')
        .map(|s| s.parse().map_or(Step::Key(s), Step::Index))
        .collect())
}

fn unknown(path: &str) -> Error {
    Error::Scene(format!(
        "`{path}` is not a scene key (docs/scenes.md lists them; an array's entries are numbered from 0, e.g. `black_hole.0.spin`)"
    ))
}

impl Scene {
    /// Every key of the scene as one TOML table (what [`Scene::to_toml`]
    /// writes).
    pub fn to_table(&self) -> Result<toml::Table> {
        let text = self.to_toml()?;
        text.parse()
            .map_err(|e| Error::Scene(format!("reading the scene's own TOML back: {e}")))
    }

    /// The value at the dotted `path` (a table for a table's path).
    pub fn key(&self, path: &str) -> Result<toml::Value> {
        let mut value = toml::Value::Table(self.to_table()?);
        for step in steps(path)? {
            let next = match (step, &value) {
                (Step::Key(k), toml::Value::Table(t)) => t.get(k),
                (Step::Index(i), toml::Value::Array(a)) => a.get(i),
                _ => None,
            };
            value = next.cloned().ok_or_else(|| unknown(path))?;
        }
        Ok(value)
    }

    /// The scene with the key at `path` set to `value`, parsed and
    /// validated as a file would be (a key the schema does not know, a
    /// value of the wrong type or out of range: the file's message, naming
    /// the key and the value). A table of the path that the scene does not
    /// have yet is made; an array is grown by one entry at its end.
    pub fn with_key(&self, path: &str, value: toml::Value) -> Result<Scene> {
        let mut root = toml::Value::Table(self.to_table()?);
        let steps = steps(path)?;
        let mut here = &mut root;
        for (n, step) in steps.iter().enumerate() {
            let last = n + 1 == steps.len();
            here = match (step, here) {
                (Step::Key(k), toml::Value::Table(t)) => {
                    if last {
                        t.insert((*k).to_string(), value);
                        break;
                    }
                    t.entry((*k).to_string())
                        .or_insert_with(|| toml::Value::Table(toml::Table::new()))
                }
                (Step::Index(i), toml::Value::Array(a)) if *i <= a.len() => {
                    if *i == a.len() {
                        a.push(toml::Value::Table(toml::Table::new()));
                    }
                    if last {
                        a[*i] = value;
                        break;
                    }
                    &mut a[*i]
                }
                _ => return Err(unknown(path)),
            };
        }
        let text = toml::to_string(&root).map_err(|e| Error::Scene(format!("`{path}`: {e}")))?;
        // The message without the generated text's place (`origin:line: `):
        // the key and the value name what was wrong.
        let origin = "<scene key>";
        Scene::from_toml(&text, origin).map_err(|e| match e {
            Error::Scene(m) => Error::Scene(
                m.strip_prefix(origin)
                    .and_then(|rest| {
                        rest.trim_start_matches(|c: char| c == ':' || c.is_ascii_digit())
                            .strip_prefix(' ')
                    })
                    .map_or(m.clone(), str::to_string),
            ),
            other => other,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_key_reads_and_writes_back_through_the_schema() {
        let scene = Scene::load("gargantua").expect("preset");
        let spin = scene.key("black_hole.0.spin").expect("spin");
        assert_eq!(spin.as_float(), Some(scene.black_holes[0].spin));
        let wider = scene
            .with_key("camera.vfov_deg", toml::Value::Float(30.0))
            .expect("valid");
        assert_eq!(wider.camera.vfov_deg, 30.0);
        assert_eq!(wider.black_holes, scene.black_holes, "the rest kept");
        let spun = scene
            .with_key("black_hole.0.spin", toml::Value::Float(0.5))
            .expect("valid");
        assert_eq!(spun.black_holes[0].spin, 0.5);
    }

    #[test]
    fn a_bad_key_or_value_is_refused_with_the_files_message() {
        let scene = Scene::load("default").expect("preset");
        let msg = |r: Result<Scene>| r.err().map(|e| e.to_string()).unwrap_or_default();
        let wrong = msg(scene.with_key("camera.vfov_deg", toml::Value::Float(-5.0)));
        assert!(wrong.starts_with("camera.vfov_deg = -5"), "{wrong}");
        let typo = msg(scene.with_key("camera.vfov", toml::Value::Float(5.0)));
        assert!(typo.contains("vfov"), "{typo}");
        let kind = msg(scene.with_key("camera.vfov_deg", toml::Value::String("wide".into())));
        assert!(kind.contains("vfov_deg"), "{kind}");
        assert!(scene.key("camera.nothing").is_err());
        assert!(scene.key("camera..up").is_err());
        assert!(scene.key("black_hole.7.spin").is_err());
    }
}
