//! Counts in messages and reports, with the noun in the right number: "1 face", "3 faces".

use std::fmt;

/// `n` followed by `singular` when `n` is 1 and by `plural` otherwise.
pub(crate) fn counted<'a>(n: usize, singular: &'a str, plural: &'a str) -> Counted<'a> {
    Counted {
        n,
        noun: if n == 1 { singular } else { plural },
    }
}

/// A count and its noun, displayed as `"{n} {noun}"`.
pub(crate) struct Counted<'a> {
    n: usize,
    noun: &'a str,
}

impl fmt::Display for Counted<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{} {}", self.n, self.noun)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn one_takes_the_singular_and_every_other_count_the_plural() {
        let faces = |n| counted(n, "face", "faces").to_string();
        assert_eq!(faces(0), "0 faces");
        assert_eq!(faces(1), "1 face");
        assert_eq!(faces(2), "2 faces");
        assert_eq!(counted(1, "vertex", "vertices").to_string(), "1 vertex");
    }
}
