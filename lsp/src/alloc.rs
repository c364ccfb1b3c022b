//! The allocator of the `rapid` binary: mimalloc, for Rust's allocations and
//! for tree-sitter's (its C code allocates every node of every tree with
//! `malloc`). Parsing is allocation-heavy and `rapid check` parses on every
//! core; with glibc's malloc the threads contend for its arenas and the
//! trees are spread over more memory.

#[global_allocator]
static GLOBAL: mimalloc::MiMalloc = mimalloc::MiMalloc;

/// Makes tree-sitter allocate with mimalloc too. Must run before any
/// tree-sitter object exists: first thing in `main`.
#[allow(unsafe_code)]
pub fn init() {
    let allocator = tree_sitter::Allocator {
        malloc: libmimalloc_sys::mi_malloc,
        calloc: libmimalloc_sys::mi_calloc,
        realloc: libmimalloc_sys::mi_realloc,
        free: libmimalloc_sys::mi_free,
    };
    // SAFETY: called once, at the start of `main` on the main thread,
    // before any parser, tree or query exists (so nothing allocated with
    // the previous allocator is freed with this one); the four functions
    // have the C signatures and semantics tree-sitter expects.
    unsafe { tree_sitter::set_allocator(Some(allocator)) }
}

/// Turns transparent huge pages off for this process: for steady latency
/// in the server, and for less memory and time in `rapid check`.
///
/// mimalloc advises the kernel to back its regions with 2 MiB pages. The
/// first touch of such a page then zeroes all of it, and memory mimalloc
/// gave back to the kernel is faulted in again that way when a later
/// request reuses it. In the server that showed as completion requests of
/// 10 to 20 ms (all of it zeroing pages in the kernel) among requests of
/// 0.5 ms. With 4 KiB pages the same requests stay under 5 ms. `rapid
/// check` releases each part of a project once checked, and the next part
/// faults the memory in again: with huge pages, zeroing them was a fifth of
/// its time on two threads, and its peak resident memory a third more
/// (BENCHMARKS.md). Returns whether the kernel took the setting (Linux
/// only).
#[cfg(target_os = "linux")]
#[allow(unsafe_code)]
pub fn no_huge_pages() -> bool {
    let off: libc::c_ulong = 1;
    let unused: libc::c_ulong = 0;
    // SAFETY: PR_SET_THP_DISABLE takes one integer argument (the flag) and
    // the rest zero; it changes only how the kernel backs this process's
    // memory from now on, never the contents of memory already in use.
    unsafe { libc::prctl(libc::PR_SET_THP_DISABLE, off, unused, unused, unused) == 0 }
}

#[cfg(not(target_os = "linux"))]
pub fn no_huge_pages() -> bool {
    false
}
