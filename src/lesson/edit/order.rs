//! Where steps go: a step's tables given places in the file when steps move (so the file reads
//! them in their new order and tables outside the steps stay put), and which steps are still in
//! their saved order.

use toml_edit::{Item, Table};

/// Calls `f` on each table a step is written as: itself, then any `[steps.x]` or
/// `[[steps.x]]` within it.
fn each_table(t: &mut Table, f: &mut impl FnMut(&mut Table)) {
    f(t);
    for (_, item) in t.iter_mut() {
        match item {
            Item::Table(sub) if !sub.is_dotted() => each_table(sub, f),
            Item::ArrayOfTables(a) => a.iter_mut().for_each(|sub| each_table(sub, f)),
            _ => {}
        }
    }
}

/// The steps written in the file in the order `order` gives (`order[i]` is the step that is to be
/// written `i`-th; the array already holds them in that order after a move, or is reordered here
/// after a copy). Every table keeps a place in the file a step's tables had, so tables outside
/// the steps stay where they were.
pub(super) fn renumber(steps: &mut toml_edit::ArrayOfTables, order: &[usize]) {
    // The place each table is written at: its own, or the one before it when it has none (a
    // table made here is written after the table before it).
    let mut last = 0;
    let mut places: Vec<Vec<isize>> = Vec::new();
    for t in steps.iter_mut() {
        let mut own = Vec::new();
        each_table(t, &mut |table| {
            last = table.position().unwrap_or(last);
            own.push(last);
        });
        places.push(own);
    }
    let mut free: Vec<isize> = places.iter().flatten().copied().collect();
    free.sort_unstable();
    // Taken out in the new order and written back with the places in ascending order.
    let mut tables: Vec<Table> = Vec::new();
    while !steps.is_empty() {
        tables.push(steps.remove(0));
    }
    let mut next = free.into_iter();
    let mut reordered: Vec<Table> = Vec::with_capacity(tables.len());
    let mut slots: Vec<Option<Table>> = tables.into_iter().map(Some).collect();
    for &k in order {
        if let Some(mut t) = slots.get_mut(k).and_then(Option::take) {
            each_table(&mut t, &mut |table| table.set_position(next.next()));
            reordered.push(t);
        }
    }
    for t in reordered {
        steps.push(t);
    }
}

/// Which entries with a rank lie on a longest run of ranks increasing from first to last (the
/// steps still in their saved order); entries without one (new steps) are on none.
pub(super) fn in_order(ranks: &[Option<usize>]) -> Vec<bool> {
    // longest[i]: the length of the longest increasing run ending at i; before[i]: the entry
    // before i on it.
    let n = ranks.len();
    let mut longest = vec![0usize; n];
    let mut before: Vec<Option<usize>> = vec![None; n];
    for i in 0..n {
        let Some(r) = ranks[i] else { continue };
        longest[i] = 1;
        for j in 0..i {
            if ranks[j].is_some_and(|q| q < r) && longest[j] + 1 > longest[i] {
                longest[i] = longest[j] + 1;
                before[i] = Some(j);
            }
        }
    }
    let mut on = vec![false; n];
    let mut at = (0..n)
        .filter(|&i| longest[i] > 0)
        .max_by_key(|&i| (longest[i], usize::MAX - i));
    while let Some(i) = at {
        on[i] = true;
        at = before[i];
    }
    on
}
