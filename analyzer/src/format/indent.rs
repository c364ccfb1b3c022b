//! The indentation unit: configured, or the text's own.
//!
//! Indentation is measured in columns, a tab reaching the next multiple of
//! [`TAB_WIDTH`]: RobotStudio writes a routine's statements after a tab
//! and four spaces, and a line at the right column is at the right column
//! whatever characters took it there.

use super::collect::Depth;

/// How wide a tab is: RobotStudio's and most editors' default.
pub(super) const TAB_WIDTH: usize = 4;

/// One level of indentation, which of the steps that RAPID code writes
/// both ways are indented, and how new indentation is written.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(super) struct Unit {
    /// Columns per level.
    pub width: usize,
    /// The module body is one level in (else at the module's column,
    /// routine bodies one level in).
    pub module: bool,
    /// `CASE` and `DEFAULT` are one level inside `TEST` (else at its
    /// column, their statements one level in).
    pub cases: bool,
    /// Indentation is written with tabs (and spaces for what is left),
    /// else with spaces.
    pub tabs: bool,
}

impl Unit {
    pub fn spaces(width: usize) -> Unit {
        Unit {
            width,
            module: true,
            cases: true,
            tabs: false,
        }
    }

    /// The number of levels a line at `depth` is indented by.
    fn levels(&self, depth: Depth) -> usize {
        depth.blocks
            + if self.module { depth.module } else { 0 }
            + if self.cases { depth.cases } else { 0 }
    }

    /// The column of a line at `depth`.
    pub fn column(&self, depth: Depth) -> usize {
        self.levels(depth) * self.width
    }

    /// The indentation of a line at `depth`.
    pub fn indent(&self, depth: Depth) -> String {
        self.render(self.column(depth))
    }

    /// The indentation that reaches `col`.
    pub fn render(&self, col: usize) -> String {
        if self.tabs {
            let mut s = "\t".repeat(col / TAB_WIDTH);
            s.extend(std::iter::repeat_n(' ', col % TAB_WIDTH));
            s
        } else {
            " ".repeat(col)
        }
    }

    /// One level more than `indent`.
    pub fn deeper(&self, indent: &str) -> String {
        let col = columns(indent) + self.width;
        if self.tabs {
            self.render(col)
        } else {
            format!("{indent}{}", " ".repeat(self.width))
        }
    }
}

/// The column reached after `s` from column 0 (a tab goes to the next
/// multiple of [`TAB_WIDTH`]).
pub(super) fn columns(s: &str) -> usize {
    columns_from(0, s)
}

/// The column reached after `s` from column `start`.
pub(super) fn columns_from(start: usize, s: &str) -> usize {
    s.chars().fold(start, |col, c| {
        if c == '\t' {
            (col / TAB_WIDTH + 1) * TAB_WIDTH
        } else {
            col + 1
        }
    })
}

/// The unit that the most structure lines of a text already follow, from
/// their depths and indentation as written: 4, 2, 3, 8 or 1 columns per
/// level, with the module body and the cases of `TEST` indented or not; new
/// indentation written with tabs if most of the lines that go a tab's width
/// in or more start with one.
///
/// A unit counts only if at least one indented line follows it: a text
/// written flat or on one line gets the default, 4 spaces with the module
/// body and `CASE` indented, except a module of declarations only
/// (`declarations_only`: no routine, record or block anywhere) at column
/// 0, which keeps its body there. A unit must fit at least half of the lines.
/// Failing that (a text indented at random in places), the module body
/// goes where most of the module's own lines (declarations, routines'
/// first and last lines) are, so a module whose routines sit at column 0
/// keeps them there and a stray line is the one to move: the unit is the
/// one of those that fits the most lines if it fits at least a third of
/// them, else 4 columns with `CASE` indented. Ties go to the earlier in
/// that order (so to the default).
pub(super) fn detect<'a>(
    lines: impl Iterator<Item = (Depth, &'a str)> + Clone,
    declarations_only: bool,
) -> Unit {
    let (mut total, mut flat, mut indented) = (0usize, 0usize, 0usize);
    for (depth, indent) in lines.clone() {
        total += usize::from(!depth.is_zero());
        if depth.is_module_body() {
            if columns(indent) == 0 {
                flat += 1;
            } else {
                indented += 1;
            }
        }
    }
    let fits = |unit: &Unit| {
        lines
            .clone()
            .filter(|(depth, indent)| !depth.is_zero() && unit.column(*depth) == columns(indent))
            .count()
    };
    let unit = match best(&all_units(), lines.clone()) {
        // not one line indented: a module of declarations only, all at
        // column 0, keeps its body there (it is what the fallback below
        // makes of one with a few stray lines, so formatting it again
        // must not indent it); any other text written flat or on one line
        // gets the default
        None if declarations_only && flat > 0 && flat == total => Unit {
            module: false,
            ..Unit::spaces(4)
        },
        None => Unit::spaces(4),
        Some(unit) if fits(&unit) * 2 >= total => unit,
        Some(_) => {
            let module = flat <= indented;
            let same: Vec<Unit> = all_units()
                .into_iter()
                .filter(|u| u.module == module)
                .collect();
            best(&same, lines.clone())
                .filter(|unit| fits(unit) * 3 >= total)
                .unwrap_or(Unit {
                    module,
                    ..Unit::spaces(4)
                })
        }
    };
    // Tabs or spaces: as most of the lines that go a tab's width in or
    // more start (a line left of the first tab stop cannot start with a
    // tab: it says nothing about how deeper lines are written).
    let (mut tab, mut space) = (0usize, 0usize);
    for (depth, indent) in lines {
        if unit.column(depth) < TAB_WIDTH {
            continue;
        }
        match indent.bytes().next() {
            Some(b'\t') => tab += 1,
            Some(_) => space += 1,
            None => {}
        }
    }
    Unit {
        tabs: tab > space,
        ..unit
    }
}

/// The unit of one item of a module (a routine, a run of declarations)
/// whose lines as written are given: another unit than `file`'s only if
/// the item has at least three lines, that unit fits at least three
/// quarters of them and more of them than `file`'s (a routine pasted in
/// from a file written another way keeps its own indentation; a routine
/// indented at random gets the file's). New indentation is written as in
/// the file.
pub(super) fn refine<'a>(file: &Unit, lines: impl Iterator<Item = (Depth, &'a str)>) -> Unit {
    let lines: Vec<(Depth, &str)> = lines.filter(|(d, _)| !d.is_zero()).collect();
    if lines.len() < 3 {
        return file.clone();
    }
    let fits = |unit: &Unit| {
        lines
            .iter()
            .filter(|(depth, indent)| unit.column(*depth) == columns(indent))
            .count()
    };
    let own = fits(file);
    let Some(unit) = best(&all_units(), lines.iter().copied()) else {
        return file.clone();
    };
    let n = fits(&unit);
    if n > own && n * 4 >= lines.len() * 3 {
        Unit {
            tabs: file.tabs,
            ..unit
        }
    } else {
        file.clone()
    }
}

/// Every unit [`detect`] chooses from, in order of preference.
fn all_units() -> Vec<Unit> {
    let mut units = Vec::new();
    for width in [4, 2, 3, 8, 1] {
        for module in [true, false] {
            for cases in [true, false] {
                units.push(Unit {
                    width,
                    module,
                    cases,
                    tabs: false,
                });
            }
        }
    }
    units
}

/// The candidate most lines fit (the first of equals), among those that at
/// least one indented line fits.
fn best<'a>(candidates: &[Unit], lines: impl Iterator<Item = (Depth, &'a str)>) -> Option<Unit> {
    // for each candidate: lines that fit, and lines indented that fit
    let mut score = vec![(0usize, 0usize); candidates.len()];
    for (depth, indent) in lines {
        if depth.is_zero() {
            continue;
        }
        let col = columns(indent);
        for (unit, (fit, evidence)) in candidates.iter().zip(score.iter_mut()) {
            if unit.column(depth) == col {
                *fit += 1;
                if col > 0 {
                    *evidence += 1;
                }
            }
        }
    }
    let mut best: Option<(usize, usize)> = None;
    for (i, &(fit, evidence)) in score.iter().enumerate() {
        if evidence > 0 && best.is_none_or(|(_, b)| fit > b) {
            best = Some((i, fit));
        }
    }
    best.map(|(i, _)| candidates[i].clone())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn depth(module: usize, cases: usize, blocks: usize) -> Depth {
        Depth {
            module,
            cases,
            blocks,
        }
    }

    #[test]
    fn the_unit_most_lines_follow_wins() {
        let four = [
            (depth(1, 0, 0), "    "),
            (depth(1, 0, 1), "        "),
            (depth(1, 0, 1), "        "),
            (depth(1, 0, 0), "  "),
        ];
        assert_eq!(detect(four.into_iter(), false), Unit::spaces(4));
        let tabs = [
            (depth(1, 0, 0), "\t"),
            (depth(1, 0, 1), "\t\t"),
            (depth(1, 0, 2), "\t\t\t"),
            (depth(1, 0, 1), "        "),
        ];
        let unit = detect(tabs.into_iter(), false);
        assert_eq!((unit.width, unit.tabs), (4, true));
        assert_eq!(unit.indent(depth(1, 0, 1)), "\t\t");
        // RobotStudio's statements: a tab and four spaces
        let studio = [
            (depth(1, 0, 0), "\t"),
            (depth(1, 0, 1), "\t    "),
            (depth(1, 0, 1), "\t    "),
        ];
        assert_eq!(detect(studio.into_iter(), false).width, 4);
        let one = [(depth(1, 0, 0), " "), (depth(1, 0, 0), " ")];
        assert_eq!(detect(one.into_iter(), false).width, 1);
        // no unit fits half of the lines: the default
        let random = [
            (depth(1, 0, 0), "      "),
            (depth(1, 0, 0), "      "),
            (depth(1, 0, 0), " "),
            (depth(1, 0, 1), "      "),
        ];
        assert_eq!(detect(random.into_iter(), false), Unit::spaces(4));
    }

    #[test]
    fn module_bodies_and_cases_at_their_parents_column_are_found() {
        let flat_module = [
            (depth(1, 0, 0), ""),
            (depth(1, 0, 0), ""),
            (depth(1, 0, 1), "    "),
            (depth(1, 0, 2), "        "),
        ];
        let unit = detect(flat_module.into_iter(), false);
        assert_eq!((unit.width, unit.module, unit.cases), (4, false, true));
        assert_eq!(unit.indent(depth(1, 0, 0)), "");
        assert_eq!(unit.indent(depth(1, 0, 2)), "        ");
        let cases = [
            (depth(1, 0, 1), "        "),
            (depth(1, 1, 1), "        "),
            (depth(1, 1, 2), "            "),
            (depth(1, 1, 1), "        "),
            (depth(1, 1, 2), "            "),
        ];
        let unit = detect(cases.into_iter(), false);
        assert_eq!((unit.module, unit.cases), (true, false));
    }

    #[test]
    fn flat_text_gets_the_default() {
        let flat = [
            (depth(1, 0, 0), ""),
            (depth(1, 0, 1), ""),
            (depth(1, 0, 2), ""),
        ];
        assert_eq!(detect(flat.into_iter(), false), Unit::spaces(4));
        assert_eq!(detect(std::iter::empty(), true), Unit::spaces(4));
    }

    #[test]
    fn declarations_only_at_column_0_stay_there() {
        // what a module of declarations with a stray indented line
        // becomes after one formatting: it must be a fixed point
        let data = [
            (depth(1, 0, 0), ""),
            (depth(1, 0, 0), ""),
            (depth(1, 0, 0), ""),
        ];
        let unit = detect(data.into_iter(), true);
        assert_eq!((unit.module, unit.width), (false, 4));
        // a routine written on the module's line is not a declaration
        assert_eq!(detect(data.into_iter(), false), Unit::spaces(4));
        let stray = [
            (depth(1, 0, 0), ""),
            (depth(1, 0, 0), "  "),
            (depth(1, 0, 0), ""),
            (depth(1, 0, 0), ""),
        ];
        assert!(!detect(stray.into_iter(), true).module);
    }

    #[test]
    fn a_module_at_column_0_stays_there_whatever_a_few_lines_say() {
        // routines at column 0, their bodies at no one width, and a
        // routine's first and last lines typed one space in
        let mut lines = Vec::new();
        for r in 0..40 {
            let header = if r == 5 { " " } else { "" };
            lines.push((depth(1, 0, 0), header));
            for k in 0..20 {
                lines.push((depth(1, 0, 1), ["  ", "   ", "     ", "      "][k % 4]));
            }
            lines.push((depth(1, 0, 0), header));
        }
        let unit = detect(lines.iter().copied(), false);
        assert!(!unit.module, "{unit:?}");
        assert_eq!(unit.indent(depth(1, 0, 0)), "");
        // and with the bodies at one width, that width
        let mut lines = vec![(depth(1, 0, 0), " "), (depth(1, 0, 1), " ")];
        for _ in 0..10 {
            lines.extend([
                (depth(1, 0, 0), ""),
                (depth(1, 0, 1), "  "),
                (depth(1, 0, 2), "    "),
                (depth(1, 0, 0), ""),
            ]);
        }
        let unit = detect(lines.iter().copied(), false);
        assert_eq!((unit.width, unit.module), (2, false));
    }

    #[test]
    fn tabs_reach_the_next_stop() {
        assert_eq!(columns("\t"), 4);
        assert_eq!(columns("  \t"), 4);
        assert_eq!(columns("\t  "), 6);
        assert_eq!(columns_from(5, "\t"), 8);
    }
}
