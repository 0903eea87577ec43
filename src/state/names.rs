//! Object names (buffer objects, queries, ...): what glGen* hands out.

use std::collections::BTreeSet;

/// `count` names that neither an object (`in_use`) nor an earlier glGen* (`reserved`) holds,
/// counting up from the largest name in use, as Mesa does, and on from 1 when that reaches
/// the last name (an application may bind 0xFFFFFFFF); they join `reserved` until bound.
///
/// # Examples
///
/// ```
/// use fflight::state::names::generate;
/// use std::collections::BTreeSet;
/// let mut reserved = BTreeSet::new();
/// assert_eq!(generate([3, 7].into_iter(), &mut reserved, 2), [8, 9]);
/// assert_eq!(generate([3, 7].into_iter(), &mut reserved, 1), [10]); // 8 and 9 are reserved
/// ```
pub fn generate(
    in_use: impl Iterator<Item = u32>,
    reserved: &mut BTreeSet<u32>,
    count: usize,
) -> Vec<u32> {
    if count == 0 {
        return Vec::new();
    }
    let in_use: Vec<u32> = in_use.collect();
    let largest = in_use
        .iter()
        .chain(reserved.iter())
        .copied()
        .max()
        .unwrap_or(0);
    let names: Vec<u32> = if (u32::MAX - largest) as usize >= count {
        // Every name above the largest is free (an inclusive range: `largest + 1..` would
        // step past u32::MAX after yielding it).
        (largest + 1..=largest + count as u32).collect()
    } else {
        let used: BTreeSet<u32> = in_use.into_iter().chain(reserved.iter().copied()).collect();
        let first = largest.wrapping_add(1).max(1);
        (first..=u32::MAX)
            .chain(1..first)
            .filter(|name| !used.contains(name))
            .take(count)
            .collect()
    };
    reserved.extend(&names);
    names
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_after_the_last_one_start_again_from_1() {
        // Found by the entry-point sweep: glBindTexture(target, 0xFFFFFFFF) then glGenTextures
        // gave one name (the one in use) for any count.
        let mut reserved = BTreeSet::new();
        let names = generate([u32::MAX, 2].into_iter(), &mut reserved, 3);
        assert_eq!(names, vec![1, 3, 4]);
        assert_eq!(generate([u32::MAX].into_iter(), &mut reserved, 1), vec![2]);
        assert_eq!(
            generate([7].into_iter(), &mut BTreeSet::new(), 2),
            vec![8, 9]
        );
    }
}
