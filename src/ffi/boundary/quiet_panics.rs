//! Panics caught at the C boundary stay quiet: the host's terminal gets no "thread panicked"
//! line and no backtrace, only the status and the recorded message (which names where it
//! happened).
//!
//! Rust prints a panic from the process-wide panic hook, before any `catch_unwind` sees it. So
//! the first guarded call installs a hook that, while a guarded call runs on the panicking
//! thread, only notes the panic's location for the message; everywhere else (the host's own
//! Rust code, if any) it hands the panic to the hook that was there before. A host that installs
//! its own hook afterwards replaces this one, and then decides itself what is printed.

use std::any::Any;
use std::cell::Cell;
use std::panic::{AssertUnwindSafe, PanicHookInfo, catch_unwind};
use std::sync::Once;

thread_local! {
    /// How many guarded calls are running on this thread (a guarded call may, through a C
    /// callback, run another).
    static GUARDED_DEPTH: Cell<u32> = const { Cell::new(0) };
    /// Where the last quiet panic on this thread happened, `file:line`.
    static LAST_LOCATION: Cell<Option<String>> = const { Cell::new(None) };
}

static INSTALL: Once = Once::new();

/// `catch_unwind(body)`, with a panic inside it kept off stderr.
pub(crate) fn catch_quietly<R>(body: impl FnOnce() -> R) -> Result<R, Box<dyn Any + Send>> {
    INSTALL.call_once(install_over_current_hook);
    // The depth is restored even when `body` unwinds, since the panic is caught right here.
    let entered = GUARDED_DEPTH
        .try_with(|depth| depth.set(depth.get() + 1))
        .is_ok();
    let result = catch_unwind(AssertUnwindSafe(body));
    if entered {
        let _ = GUARDED_DEPTH.try_with(|depth| depth.set(depth.get() - 1));
    }
    result
}

/// The location, as `file:line`, of the last panic caught quietly on this thread (taken: a
/// second call gives `None`).
pub(crate) fn last_panic_location() -> Option<String> {
    LAST_LOCATION.try_with(Cell::take).ok().flatten()
}

/// Wraps the current panic hook in one that is silent inside guarded calls.
fn install_over_current_hook() {
    let previous = std::panic::take_hook();
    std::panic::set_hook(Box::new(move |info: &PanicHookInfo<'_>| {
        // Thread-local storage being torn down counts as unguarded: print as before.
        let guarded = GUARDED_DEPTH.try_with(Cell::get).unwrap_or(0) > 0;
        if guarded {
            let location = info
                .location()
                .map(|l| format!("{}:{}", l.file(), l.line()));
            let _ = LAST_LOCATION.try_with(|last| last.set(location));
        } else {
            previous(info);
        }
    }));
}

#[cfg(test)]
mod tests {
    use super::*;

    thread_local! {
        static PRINTED: Cell<u32> = const { Cell::new(0) };
    }

    #[test]
    fn guarded_panics_reach_no_hook_and_others_do() {
        // A stand-in for the host's hook that counts this thread's panics (and still prints
        // them, so that other tests' failures stay readable), under the quiet one.
        let original = std::panic::take_hook();
        std::panic::set_hook(Box::new(move |info| {
            PRINTED.with(|n| n.set(n.get() + 1));
            original(info);
        }));
        install_over_current_hook();

        let outside = catch_unwind(|| panic!("outside any guarded call"));
        assert!(outside.is_err());
        assert_eq!(
            PRINTED.with(Cell::get),
            1,
            "an unguarded panic reaches the hook"
        );

        let inside = catch_quietly(|| panic!("inside a guarded call"));
        assert!(inside.is_err());
        assert_eq!(PRINTED.with(Cell::get), 1, "a guarded panic stays quiet");
        let location = last_panic_location().expect("its location is kept");
        assert!(
            location.starts_with("src/ffi/boundary/quiet_panics.rs:"),
            "{location}"
        );
        assert_eq!(GUARDED_DEPTH.with(Cell::get), 0, "the depth is restored");
    }
}
