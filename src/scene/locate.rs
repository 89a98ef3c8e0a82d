//! Finding where a key sits in a TOML source, for error messages.

use toml::de::{DeTable, DeValue};

/// One step of a key path: a table key or an array index.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Seg {
    Key(&'static str),
    Idx(usize),
}

/// `black_hole[0].rs` style.
pub fn display_path(path: &[Seg]) -> String {
    let mut s = String::new();
    for seg in path {
        match seg {
            Seg::Key(k) => {
                if !s.is_empty() {
                    s.push('.');
                }
                s.push_str(k);
            }
            Seg::Idx(i) => s.push_str(&format!("[{i}]")),
        }
    }
    s
}

/// 1-based line of byte offset `pos`.
pub fn line_of(src: &str, pos: usize) -> usize {
    src.as_bytes()[..pos.min(src.len())]
        .iter()
        .filter(|&&b| b == b'\n')
        .count()
        + 1
}

/// The trimmed text of the line holding byte offset `pos`.
pub fn line_text(src: &str, pos: usize) -> Option<String> {
    let pos = pos.min(src.len());
    let start = src[..pos].rfind('\n').map_or(0, |i| i + 1);
    let end = src[pos..].find('\n').map_or(src.len(), |i| pos + i);
    let t = src.get(start..end)?.trim();
    // A message stays one readable line: long lines are cut.
    const MAX: usize = 80;
    let shown: String = t.chars().take(MAX).collect();
    let cut = t.chars().nth(MAX).is_some();
    (!t.is_empty()).then(|| if cut { format!("{shown}...") } else { shown })
}

/// Line of the deepest part of `path` present in `src` (the key itself if it
/// is written, else its table header); `None` if the source does not parse.
pub fn line_of_key(src: &str, path: &[Seg]) -> Option<usize> {
    let root = DeTable::parse(src).ok()?;
    let mut table: &DeTable<'_> = root.get_ref();
    let mut best: Option<usize> = None;
    let mut i = 0;
    while i < path.len() {
        let Seg::Key(k) = path[i] else { return best };
        let (key, value) = table.get_key_value(k)?;
        best = Some(key.span().start);
        i += 1;
        let mut v: &DeValue<'_> = value.get_ref();
        if let (Some(Seg::Idx(n)), DeValue::Array(arr)) = (path.get(i), v) {
            let item = arr.get(*n)?;
            best = Some(item.span().start);
            v = item.get_ref();
            i += 1;
        }
        match v {
            DeValue::Table(t) => table = t,
            _ => break,
        }
    }
    best.map(|p| line_of(src, p))
}

/// `text` with every number longer than 16 characters written in scientific
/// notation (`1e308`, not its 309 digits), so a message stays one short line.
pub fn compact_numbers(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    let mut token = String::new();
    let flush = |token: &mut String, out: &mut String| {
        match token.parse::<f64>() {
            Ok(v) if token.len() > 16 => out.push_str(&format!("{v:e}")),
            _ => out.push_str(token),
        }
        token.clear();
    };
    for c in text.chars() {
        if c.is_ascii_digit() || c == '.' || ((c == 'e' || c == 'E') && !token.is_empty()) {
            token.push(c);
        } else if (c == '-' || c == '+') && (token.is_empty() || token.ends_with(['e', 'E'])) {
            if token.is_empty() {
                out.push(c);
            } else {
                token.push(c);
            }
        } else {
            flush(&mut token, &mut out);
            out.push(c);
        }
    }
    flush(&mut token, &mut out);
    out
}

/// For a name the parser refused ("unknown field `x`, expected one of `a`,
/// `b`", "unknown variant `x`", or an unquoted key that is not plain ASCII):
/// when the name holds characters that are not plain ASCII (a Cyrillic `а`
/// for a Latin `a`, a zero-width space), the text naming each by code point
/// and position, and the known name it resembles. `line` is the source line
/// of the error; `known` the names a scene file may use.
pub fn odd_name_hint(msg: &str, line: Option<&str>, known: &[String]) -> Option<String> {
    let (name, expected): (String, Vec<&str>) = if let Some(rest) = msg
        .strip_prefix("unknown field `")
        .or_else(|| msg.strip_prefix("unknown variant `"))
    {
        let (name, tail) = rest.split_once('`')?;
        (
            name.to_string(),
            tail.split('`').skip(1).step_by(2).collect(),
        )
    } else if msg.starts_with("invalid unquoted key") {
        let key = line?.split('=').next()?;
        let key = key.trim().trim_matches(|c| c == '[' || c == ']').trim();
        let last = key.rsplit('.').next()?.trim();
        (last.to_string(), Vec::new())
    } else {
        return None;
    };
    let odd: Vec<String> = name
        .chars()
        .enumerate()
        .filter(|(_, c)| !c.is_ascii_graphic())
        .map(|(i, c)| format!("U+{:04X} {c:?} at character {}", u32::from(c), i + 1))
        .collect();
    if odd.is_empty() {
        return None;
    }
    let len = name.chars().count();
    // A guess only where most of the name is plain: the odd characters are
    // look-alikes in a word, not a word of another script.
    let resembles = |known: &str| {
        2 * odd.len() <= len
            && known.chars().count() == len
            && known
                .chars()
                .zip(name.chars())
                .all(|(k, n)| k == n || !n.is_ascii_graphic())
    };
    // The message stays one short line: three characters at most.
    let shown = if odd.len() > 3 {
        format!("{} and {} more", odd[..3].join(", "), odd.len() - 3)
    } else {
        odd.join(", ")
    };
    let guess = expected
        .into_iter()
        .find(|k| resembles(k))
        .or_else(|| known.iter().map(String::as_str).find(|k| resembles(k)));
    let name: String = name.chars().take(24).collect();
    Some(format!(
        "; `{name}` holds {shown}, not plain ASCII{}",
        guess
            .map(|g| format!(": did you mean `{g}`?"))
            .unwrap_or_default()
    ))
}

#[cfg(test)]
mod tests {
    #[test]
    fn a_look_alike_character_is_pointed_at() {
        let h = super::odd_name_hint(
            "unknown field `c\u{430}mera`, expected one of `camera`, `disk`",
            None,
            &[],
        )
        .expect("a hint");
        assert!(h.contains("U+0430") && h.contains("character 2"), "{h}");
        assert!(h.contains("did you mean `camera`?"), "{h}");
        let known = ["camera".to_string(), "disk".to_string()];
        let h = super::odd_name_hint(
            "invalid unquoted key, expected letters",
            Some("[c\u{430}mera]"),
            &known,
        )
        .expect("a hint");
        assert!(h.contains("did you mean `camera`?"), "{h}");
        assert_eq!(
            super::odd_name_hint("unknown field `camra`, expected `camera`", None, &[]),
            None
        );
    }

    #[test]
    fn long_numbers_are_compacted() {
        let big = format!("{}", 1e300f64);
        let m = super::compact_numbers(&format!("x = {big}: must be at most 1e9"));
        assert_eq!(m, "x = 1e300: must be at most 1e9");
        assert_eq!(
            super::compact_numbers("line 12: 3.5 and -2"),
            "line 12: 3.5 and -2"
        );
    }
}
