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

#[cfg(test)]
mod tests {
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
