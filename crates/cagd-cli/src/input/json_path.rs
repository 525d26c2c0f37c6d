//! The JSON path of a position in a text that serde_json could not read, so that a syntax
//! error (a number out of range such as `1e999`, a trailing comma) names the field it is
//! in, like every other input error (`input.points[2][1]`).

/// The byte offset of serde_json's 1-based `(line, column)` (the last byte it read), clamped
/// to the text.
fn offset(text: &str, line: usize, column: usize) -> usize {
    let start: usize = text
        .split_inclusive('\n')
        .take(line.saturating_sub(1))
        .map(str::len)
        .sum();
    start.saturating_add(column).min(text.len())
}

/// One open container: an array with the index of its current element, or an object with
/// its current key (`None` while a key is expected).
enum Frame {
    Array(usize),
    Object(Option<String>),
}

/// The path of the value being read at serde_json's `(line, column)` in `text`, starting
/// with `root`: `root`, `root[3]`, `root.points[2][1]`, .... Scans the bytes before the
/// position, the one serde_json stopped at included (structural characters are ASCII, so
/// bytes of multi-byte characters never match them); a string escape `\"` does not end a
/// string.
pub(crate) fn path_at(text: &str, line: usize, column: usize, root: &str) -> String {
    let bytes = &text.as_bytes()[..offset(text, line, column)];
    let mut stack: Vec<Frame> = Vec::new();
    let mut i = 0;
    while i < bytes.len() {
        match bytes[i] {
            b'[' => stack.push(Frame::Array(0)),
            b'{' => stack.push(Frame::Object(None)),
            // A closing bracket that is the byte serde_json stopped at (a trailing comma)
            // is still inside its container.
            b']' | b'}' if i + 1 < bytes.len() => {
                stack.pop();
            }
            b',' => match stack.last_mut() {
                Some(Frame::Array(k)) => *k += 1,
                Some(Frame::Object(key)) => *key = None,
                None => {}
            },
            b'"' => {
                let start = i + 1;
                i = start;
                while i < bytes.len() && bytes[i] != b'"' {
                    i += if bytes[i] == b'\\' { 2 } else { 1 };
                }
                if let Some(Frame::Object(key @ None)) = stack.last_mut() {
                    let end = i.min(bytes.len());
                    *key = Some(String::from_utf8_lossy(&bytes[start..end]).into_owned());
                }
            }
            _ => {}
        }
        i += 1;
    }
    let mut path = root.to_string();
    for frame in &stack {
        match frame {
            Frame::Array(k) => path.push_str(&format!("[{k}]")),
            Frame::Object(Some(key)) => {
                path.push('.');
                path.push_str(key);
            }
            Frame::Object(None) => break,
        }
    }
    path
}

#[cfg(test)]
mod tests {
    use super::*;

    fn located(text: &str) -> String {
        let e = serde_json::from_str::<serde_json::Value>(text).unwrap_err();
        path_at(text, e.line(), e.column(), "input")
    }

    #[test]
    fn names_the_field_of_a_syntax_error() {
        assert_eq!(
            located(r#"{"type":"x","points":[[0,1],[2,1e999]]}"#),
            "input.points[1][1]"
        );
        assert_eq!(
            located("[{\"a\":1},\n {\"b\":[1,2,],\"c\":0}]"),
            "input[1].b[2]"
        );
        assert_eq!(located(r#"{"k\"ey":[1e400]}"#), "input.k\\\"ey[0]");
        assert_eq!(located(r#"{"é":[0,-1e999]}"#), "input.é[1]");
        assert_eq!(located("{"), "input");
        assert_eq!(located("[1,"), "input[1]");
        assert_eq!(located(""), "input");
    }
}
