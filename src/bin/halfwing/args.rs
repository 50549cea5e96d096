//! The command line of one command: positional arguments, flags and options with a value.

use crate::failure::Failure;

/// A command's arguments split into positional ones and named options.
pub struct Args {
    positional: Vec<String>,
    named: Vec<(String, Option<String>)>,
}

impl Args {
    /// Splits `args`: `flags` take no value, `options` take the next argument. `None` when
    /// `--help` was given (the command prints its help).
    pub fn parse(
        args: &[String],
        flags: &[&str],
        options: &[&str],
    ) -> Result<Option<Self>, Failure> {
        let mut parsed = Args {
            positional: Vec::new(),
            named: Vec::new(),
        };
        let mut rest = args.iter();
        while let Some(arg) = rest.next() {
            if arg == "--help" || arg == "-h" {
                return Ok(None);
            } else if flags.contains(&arg.as_str()) {
                parsed.named.push((arg.clone(), None));
            } else if options.contains(&arg.as_str()) {
                let value = rest
                    .next()
                    .ok_or_else(|| Failure::usage(format!("{arg} needs a value")))?;
                parsed.named.push((arg.clone(), Some(value.clone())));
            } else if arg.starts_with("--") {
                return Err(Failure::usage(format!("unknown option {arg}")));
            } else {
                parsed.positional.push(arg.clone());
            }
        }
        Ok(Some(parsed))
    }

    /// Exactly `names.len()` positional arguments, named for the message when they are not.
    pub fn positional(&self, names: &[&str]) -> Result<&[String], Failure> {
        if self.positional.len() != names.len() {
            return Err(Failure::usage(format!(
                "expected {} (got {} argument{})",
                names.join(" "),
                self.positional.len(),
                if self.positional.len() == 1 { "" } else { "s" }
            )));
        }
        Ok(&self.positional)
    }

    pub fn flag(&self, name: &str) -> bool {
        self.named.iter().any(|(n, _)| n == name)
    }

    /// The last value given for `name`.
    pub fn value(&self, name: &str) -> Option<&str> {
        self.named
            .iter()
            .rev()
            .find(|(n, _)| n == name)
            .and_then(|(_, v)| v.as_deref())
    }

    /// The value of `name` parsed as a `T`.
    pub fn parsed<T: std::str::FromStr>(&self, name: &str) -> Result<Option<T>, Failure> {
        self.value(name)
            .map(|v| {
                v.parse()
                    .map_err(|_| Failure::usage(format!("{name}: cannot read {v:?} as a number")))
            })
            .transpose()
    }
}
