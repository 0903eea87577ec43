//! Selection mode (§5.2): the name stack, the hit flag with the depth range of the current
//! hit, and the hit records collected for glRenderMode to return.

/// GL_MAX_NAME_STACK_DEPTH (Mesa's value).
pub const MAX_NAME_STACK_DEPTH: usize = 64;

/// The selection state as the context keeps it: at most `capacity` values of hit records,
/// then overflow.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Selection {
    /// Whether glSelectBuffer was called: glRenderMode(GL_SELECT) needs it.
    pub buffer_given: bool,
    /// glSelectBuffer's size: the most values the hit records take.
    pub capacity: usize,
    /// The address glSelectBuffer was given: only the C layer writes through it.
    pub address: usize,
    /// The hit records written since selection mode was entered (never more than `capacity`).
    pub records: Vec<u32>,
    /// Whether a value did not fit: glRenderMode then returns -1.
    pub overflowed: bool,
    /// Hit records written, whole or cut short by the end of the buffer.
    pub hits: i32,
    /// The name stack, bottom first; always empty outside selection mode.
    pub names: Vec<u32>,
    /// The minimum and maximum window z of the primitives that hit since the last record,
    /// if any did (the hit flag).
    pub hit_depths: Option<(f32, f32)>,
}

impl Selection {
    /// A primitive hit with a vertex at window depth `z`: updates the current hit's range.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::pipeline::select::{Selection, depth_to_uint};
    /// let mut selection = Selection { capacity: 16, ..Selection::default() };
    /// selection.hit(0.5);
    /// selection.hit(0.25);
    /// assert_eq!(selection.hit_depths, Some((0.25, 0.5)));
    /// ```
    pub fn hit(&mut self, z: f32) {
        let (min, max) = self.hit_depths.get_or_insert((z, z));
        *min = min.min(z);
        *max = max.max(z);
    }

    /// Writes a hit record if there was a hit since the last one: the number of names, the
    /// minimum and maximum depth, then the names, bottom first. Clears the hit flag (§5.2).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::pipeline::select::{Selection, depth_to_uint};
    /// let mut selection = Selection { capacity: 16, ..Selection::default() };
    /// selection.names = vec![7];
    /// selection.hit(0.0);
    /// selection.write_hit_record();
    /// selection.write_hit_record(); // no hit since: nothing
    /// assert_eq!(selection.records, [1, 0, 0, 7]);
    /// assert_eq!(selection.hits, 1);
    /// ```
    pub fn write_hit_record(&mut self) {
        let Some((min, max)) = self.hit_depths.take() else {
            return;
        };
        self.value(self.names.len() as u32);
        self.value(depth_to_uint(min));
        self.value(depth_to_uint(max));
        for k in 0..self.names.len() {
            self.value(self.names[k]);
        }
        self.hits += 1;
    }

    fn value(&mut self, value: u32) {
        if self.records.len() < self.capacity {
            self.records.push(value);
        } else {
            self.overflowed = true;
        }
    }

    /// Starts a new selection pass: no records, no hit, an empty name stack.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::pipeline::select::{Selection, depth_to_uint};
    /// let mut selection = Selection { capacity: 16, ..Selection::default() };
    /// selection.names = vec![1, 2];
    /// selection.hit(0.5);
    /// selection.restart();
    /// assert!(selection.names.is_empty() && selection.hit_depths.is_none());
    /// ```
    pub fn restart(&mut self) {
        self.records.clear();
        self.overflowed = false;
        self.hits = 0;
        self.names.clear();
        self.hit_depths = None;
    }

    /// glRenderMode's return value when selection ends: the hit count, or -1 on overflow.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::pipeline::select::{Selection, depth_to_uint};
    /// let mut selection = Selection { capacity: 3, ..Selection::default() };
    /// selection.hit(1.0);
    /// selection.write_hit_record(); // 3 values: fits
    /// assert_eq!(selection.result(), 1);
    /// selection.hit(1.0);
    /// selection.write_hit_record(); // no room left
    /// assert_eq!(selection.result(), -1);
    /// ```
    pub fn result(&self) -> i32 {
        if self.overflowed { -1 } else { self.hits }
    }
}

/// A window depth in [0, 1] as a hit record holds it: multiplied by 2^32 - 1 and rounded to
/// the nearest unsigned integer (§5.2). Depths a hair outside [0, 1] (float rounding of a
/// vertex on a clip plane) are clamped.
///
/// # Examples
///
/// ```
/// use fflight::pipeline::select::depth_to_uint;
/// assert_eq!(depth_to_uint(0.0), 0);
/// assert_eq!(depth_to_uint(1.0), u32::MAX);
/// assert_eq!(depth_to_uint(1.0000001), u32::MAX);
/// ```
pub fn depth_to_uint(z: f32) -> u32 {
    (f64::from(z.clamp(0.0, 1.0)) * f64::from(u32::MAX)).round() as u32
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn depths_scale_to_the_full_unsigned_range() {
        assert_eq!(depth_to_uint(0.0), 0);
        assert_eq!(depth_to_uint(1.0), u32::MAX);
        assert_eq!(depth_to_uint(0.5), 2_147_483_648);
        assert_eq!(depth_to_uint(1.5), u32::MAX);
        assert_eq!(depth_to_uint(-0.25), 0);
    }

    #[test]
    fn a_record_cut_short_counts_as_overflow() {
        let mut s = Selection {
            capacity: 4,
            ..Selection::default()
        };
        s.names = vec![7, 8];
        s.hit(0.25);
        s.hit(0.75);
        s.write_hit_record();
        assert_eq!(s.records, [2, depth_to_uint(0.25), depth_to_uint(0.75), 7]);
        assert!(s.overflowed);
        assert_eq!(s.result(), -1);
        s.write_hit_record();
        assert_eq!(s.hits, 1, "no hit since the last record: nothing written");
    }
}
