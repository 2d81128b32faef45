//! The text lines of the writers, formatted in parallel batches and written in order.

use rayon::prelude::*;
use std::io::Write;

/// Writes `n` lines, line i formatted by `line(i, buf)`, in parallel batches written in order:
/// the same bytes as a sequential loop. Formatting floats was most of `ppm sample`'s serial
/// time (a level-2 koala writes 800k vertex and 1.6M face lines); the batches bound memory.
pub(super) fn write_lines(
    w: &mut impl Write,
    n: usize,
    line: impl Fn(usize, &mut Vec<u8>) -> std::io::Result<()> + Sync,
) -> std::io::Result<()> {
    const CHUNK: usize = 4096;
    const BATCH: usize = 64 * CHUNK;
    for start in (0..n).step_by(BATCH) {
        let end = (start + BATCH).min(n);
        let bufs = (start..end)
            .step_by(CHUNK)
            .collect::<Vec<_>>()
            .into_par_iter()
            .map(|s| {
                let mut b = Vec::with_capacity(CHUNK * 48);
                for i in s..(s + CHUNK).min(end) {
                    line(i, &mut b)?;
                }
                Ok(b)
            })
            .collect::<std::io::Result<Vec<Vec<u8>>>>()?;
        for b in bufs {
            w.write_all(&b)?;
        }
    }
    Ok(())
}

/// "3 a b c\n", as `writeln!(b, "3 {} {} {}", ..)` prints it (OFF and PLY faces).
pub(super) fn face_line(b: &mut Vec<u8>, f: [u32; 3]) -> std::io::Result<()> {
    b.push(b'3');
    for x in f {
        b.push(b' ');
        super::super::decimal::push_uint(b, x.into());
    }
    b.push(b'\n');
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The parallel writer gives the bytes of a sequential loop, across chunk and batch
    /// boundaries, and passes a line's error on.
    #[test]
    fn write_lines_is_the_sequential_text() {
        let n = 2 * 64 * 4096 + 4097;
        let mut par = Vec::new();
        write_lines(&mut par, n, |i, b| writeln!(b, "{i} {:?}", i as f64 / 7.0)).expect("vec");
        let mut seq = Vec::new();
        for i in 0..n {
            writeln!(seq, "{i} {:?}", i as f64 / 7.0).expect("vec");
        }
        assert!(par == seq);
        let err = write_lines(&mut Vec::new(), n, |i, b| {
            if i == n - 1 {
                Err(std::io::Error::other("line"))
            } else {
                writeln!(b, "{i}")
            }
        });
        assert!(err.is_err());
    }
}
