//! Text for an 80-column terminal: long lines are wrapped at spaces with a hanging indent
//! that keeps the shape of the line (a bullet's text, a table's second column, the text
//! after a short "label: "), so `explain` and error messages read well at 80 columns. A
//! single token longer than the room left (a long path) is never broken; it overflows.

/// Terminal width the program writes for.
pub(crate) const WIDTH: usize = 80;

/// The column where the continuation lines of `line` start.
fn hang(line: &[char]) -> usize {
    let lead = line.iter().take_while(|c| **c == ' ').count();
    let rest = &line[lead..];
    let starts = |p: &str| rest.iter().take(p.chars().count()).copied().eq(p.chars());
    for bullet in ["-> ", "- ", "* "] {
        if starts(bullet) {
            return lead + bullet.chars().count();
        }
    }
    // A two-column line ("  normal contact    always"): under the second column.
    if let Some(k) = rest.windows(2).position(|w| w == [' ', ' ']) {
        let col = lead + k + rest[k..].iter().take_while(|c| **c == ' ').count();
        if col <= 30 && col < line.len() {
            return col;
        }
    }
    // A short label ("hint: ", "estimated cost: "): after it.
    if let Some(k) = rest.windows(2).position(|w| w == [':', ' ']) {
        if k <= 24 {
            return lead + k + 2;
        }
    }
    lead + 2
}

/// `line` cut into lines of at most `width` characters where it can be.
fn wrap_line(line: &str, width: usize, out: &mut String) {
    let chars: Vec<char> = line.chars().collect();
    if chars.len() <= width {
        out.push_str(line);
        out.push('\n');
        return;
    }
    let indent = hang(&chars).min(width / 2);
    let mut cur: Vec<char> = chars;
    let mut first = true;
    loop {
        if cur.len() <= width {
            out.extend(cur.iter());
            out.push('\n');
            return;
        }
        let floor = if first { indent } else { indent + 1 };
        // the last space that leaves the line within the width, past the indent
        // (not before punctuation, which belongs with the word before it)
        let breakable = |k: usize| {
            cur[k] == ' ' && !matches!(cur.get(k + 1), Some(':' | ';' | ',' | '.' | ')'))
        };
        let cut = (floor..=width).rev().find(|&k| breakable(k)).or_else(|| {
            // an unbreakable token: break at the first space after it
            (width..cur.len()).find(|&k| breakable(k))
        });
        let Some(cut) = cut else {
            out.extend(cur.iter());
            out.push('\n');
            return;
        };
        let head: String = cur[..cut].iter().collect();
        out.push_str(head.trim_end());
        out.push('\n');
        let tail: Vec<char> = cur[cut..].iter().copied().skip_while(|c| *c == ' ').collect();
        if tail.is_empty() {
            return;
        }
        cur = std::iter::repeat_n(' ', indent).chain(tail).collect();
        first = false;
    }
}

/// `text` with every line wrapped to `width` columns (see the module's documentation).
pub(crate) fn wrap(text: &str, width: usize) -> String {
    let mut out = String::with_capacity(text.len() + text.len() / 16);
    for line in text.lines() {
        wrap_line(line, width, &mut out);
    }
    if !text.ends_with('\n') {
        out.pop();
    }
    out
}

#[cfg(test)]
mod tests {
    use super::wrap;

    #[test]
    fn short_lines_are_unchanged() {
        let t = "scene: x\n\n  normal contact    always\n";
        assert_eq!(wrap(t, 80), t);
        assert_eq!(wrap("a\nb", 80), "a\nb");
    }

    #[test]
    fn bullets_hang_under_their_text() {
        let t = format!("    -> {}", "word ".repeat(30).trim_end());
        let w = wrap(&t, 40);
        let lines: Vec<&str> = w.lines().collect();
        assert!(lines.len() > 3);
        assert!(lines.iter().all(|l| l.chars().count() <= 40), "{w}");
        assert!(lines[1..].iter().all(|l| l.starts_with("       word")), "{w}");
        // nothing lost, nothing added but line breaks and indents
        assert_eq!(
            w.split_whitespace().collect::<Vec<_>>(),
            t.split_whitespace().collect::<Vec<_>>()
        );
    }

    #[test]
    fn two_columns_and_labels_hang_under_the_value() {
        let w = wrap(&format!("  twist             {}", "moment M = 80 N m ".repeat(6)), 60);
        assert!(w.lines().skip(1).all(|l| l.starts_with("                    m")), "{w}");
        let w = wrap(&format!("  hint: {}", "use a larger radius ".repeat(6)), 50);
        assert!(w.lines().skip(1).all(|l| l.starts_with("        ")), "{w}");
    }

    #[test]
    fn punctuation_stays_with_its_word() {
        let w = wrap(&format!("{} 30000 : the contact slides", "x".repeat(70)), 78);
        assert!(w.lines().all(|l| !l.trim_start().starts_with(':')), "{w}");
    }

    #[test]
    fn a_long_token_overflows_whole() {
        let path = format!("/very/{}/scene.toml", "long".repeat(30));
        let w = wrap(&format!("error: {path}: cannot read"), 80);
        assert!(w.lines().any(|l| l.contains(&path)));
        assert!(w.ends_with("cannot read"));
    }
}
