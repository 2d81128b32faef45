//! Line splitting for the text formats: `\n` or `\r\n` line ends, 1-based line numbers,
//! UTF-8 checked per line.

/// Splits a byte buffer into lines without copying.
pub(crate) struct Lines<'a> {
    rest: &'a [u8],
    line_no: u64,
}

impl<'a> Lines<'a> {
    /// Lines of `bytes`, numbered from `first_line`. A leading UTF-8 byte-order mark is
    /// skipped.
    pub(crate) fn new(bytes: &'a [u8], first_line: u64) -> Self {
        Lines {
            rest: bytes.strip_prefix(b"\xef\xbb\xbf").unwrap_or(bytes),
            line_no: first_line.saturating_sub(1),
        }
    }

    /// The next line (without its line end) and its number; `Err(line)` if it is not UTF-8.
    pub(crate) fn next_line(&mut self) -> Option<(u64, Result<&'a str, u64>)> {
        if self.rest.is_empty() {
            return None;
        }
        let (line, rest) = match self.rest.iter().position(|&b| b == b'\n') {
            Some(i) => (&self.rest[..i], &self.rest[i + 1..]),
            None => (self.rest, &self.rest[self.rest.len()..]),
        };
        self.rest = rest;
        self.line_no = self.line_no.saturating_add(1);
        let line = line.strip_suffix(b"\r").unwrap_or(line);
        let no = self.line_no;
        Some((no, std::str::from_utf8(line).map_err(|_| no)))
    }

    /// The next line that is not blank once a `#` comment is removed: its number and its
    /// content before the `#`.
    pub(crate) fn next_content(&mut self) -> Option<(u64, Result<&'a str, u64>)> {
        loop {
            let (no, line) = self.next_line()?;
            match line {
                Err(e) => return Some((no, Err(e))),
                Ok(s) => {
                    let s = strip_comment(s);
                    if !s.trim().is_empty() {
                        return Some((no, Ok(s)));
                    }
                }
            }
        }
    }

    /// Number of the last line returned (0 before the first).
    pub(crate) fn line_no(&self) -> u64 {
        self.line_no
    }

    /// Bytes not yet consumed.
    pub(crate) fn remaining(&self) -> &'a [u8] {
        self.rest
    }
}

/// The part of a line before a `#` comment.
pub(crate) fn strip_comment(s: &str) -> &str {
    match s.find('#') {
        Some(i) => &s[..i],
        None => s,
    }
}
