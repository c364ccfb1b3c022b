use std::ops::Range;

use crate::check::Cx;

crate::declare_rule! {
    /// A name longer than 32 characters.
    ///
    /// ### What it checks
    /// Identifiers in RAPID are at most 32 characters long. A letter such as
    /// `Ö` is one character (one byte of the controller's Latin-1), even
    /// where the file is UTF-8.
    ///
    /// ### Why
    /// The controller rejects the module.
    ///
    /// ### Example
    /// ```rapid
    /// VAR num the_number_of_boxes_on_the_left_pallet;   ! 39 characters
    /// ```
    pub static RULE = ("E410", "name-too-long", Error);
}

/// The longest name RAPID accepts.
const MAX_NAME: usize = 32;

/// A declared name longer than RAPID accepts.
pub(crate) fn check(cx: &mut Cx<'_>, name: &str, range: Range<usize>) {
    // Names hold only Latin-1 letters, digits and `_`: one byte each on
    // the controller, one `char` here.
    let count = name.chars().count();
    if count > MAX_NAME {
        cx.report(
            &RULE,
            range,
            format!("`{name}` has {count} characters; names have at most {MAX_NAME}"),
        );
    }
}
