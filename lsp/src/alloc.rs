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
