//! The pixel comparison of the two renderings and the picture of it.
//!
//! **Tolerance: 2/255 per channel, away from silhouettes.** Both renderings are rasterized by
//! the same rasterizer (llvmpipe: the captured triangles in the core context, the legacy
//! primitives in the compatibility one), into RGBA8, with the same perspective-correct
//! interpolation of the same per-vertex colors and the same per-fragment color sum. What
//! differs is where the per-vertex values come from: fflight lights and transforms in double
//! precision and rounds the results to float; Mesa's fixed-function vertex program does it
//! in float, with llvmpipe's approximations of pow (specular and spot exponents), 1/sqrt and
//! division. The OSMesa comparisons of the test suite measure that difference: at most about
//! 5.5e-6 per color channel (docs/osmesa-differences.md, "Numerical agreement"), 1.4e-3 of
//! one 8-bit step. Interpolating and converting to 8 bits can still put the two values on
//! either side of a rounding boundary, so a pixel may differ by 1; 2 leaves a step of margin
//! for the interpolation of slightly different vertex positions (a few 1e-6 of a pixel).
//! Anything from a real lighting difference (a wrong term, a wrong light, a wrong material)
//! is many steps.
//!
//! **Silhouettes.** Which primitive covers a pixel whose center lies within about 1e-5 pixel
//! of an edge depends on those last bits of the vertex positions, so along the outline of an
//! object a pixel may show another object (or the background) in one rendering than in the
//! other. Inside an object nothing like that happens: neighboring triangles share their
//! vertices and so their colors on the shared edge. Every object has its own alpha
//! (`scene::OBJECT_ALPHAS`), so the alpha channel names the object a pixel shows: a pixel is
//! a silhouette pixel when, in either rendering, its 3x3 neighborhood shows more than one
//! object. Those pixels are counted and reported but not held to the tolerance.

use std::fmt;

/// Largest allowed difference of a channel away from silhouettes, in 8-bit steps.
pub const TOLERANCE: u8 = 2;
/// How much the difference image amplifies differences.
pub const AMPLIFY: u8 = 32;

pub struct Report {
    /// Pixels held to the tolerance (not silhouette).
    compared: usize,
    /// Of those, pixels showing an object (not the background).
    object_pixels: usize,
    silhouette: usize,
    /// Largest channel difference over the compared pixels.
    max: u8,
    /// Mean channel difference over the compared object pixels.
    mean: f64,
    /// Compared pixels with any difference.
    differing: usize,
    /// Largest channel difference over the silhouette pixels (reported only).
    silhouette_max: u8,
    /// Checks that keep the comparison meaningful, each with whether it holds.
    checks: Vec<(String, bool)>,
}

/// RGBA8 pixel `i` of `image`.
fn pixel(image: &[u8], i: usize) -> &[u8] {
    &image[4 * i..4 * i + 4]
}

/// Whether a pixel's 3x3 neighborhood shows more than one object (alpha value) in `image`.
fn object_edges(image: &[u8], width: usize, height: usize) -> Vec<bool> {
    let alpha = |x: usize, y: usize| image[4 * (y * width + x) + 3];
    let mut edges = vec![false; width * height];
    for y in 0..height {
        for x in 0..width {
            let center = alpha(x, y);
            edges[y * width + x] = (y.saturating_sub(1)..(y + 2).min(height)).any(|ny| {
                (x.saturating_sub(1)..(x + 2).min(width)).any(|nx| alpha(nx, ny) != center)
            });
        }
    }
    edges
}

/// Where the comparison excludes a pixel: an object edge in either rendering.
fn silhouettes(a: &[u8], b: &[u8], width: usize, height: usize) -> Vec<bool> {
    let (ea, eb) = (
        object_edges(a, width, height),
        object_edges(b, width, height),
    );
    ea.iter().zip(&eb).map(|(&x, &y)| x || y).collect()
}

fn channel_difference(a: &[u8], b: &[u8]) -> u8 {
    a.iter()
        .zip(b)
        .map(|(x, y)| x.abs_diff(*y))
        .max()
        .unwrap_or(0)
}

/// Compares the core-profile rendering of fflight's capture (`modern`) with the system GL's
/// fixed-function rendering (`fixed`), both RGBA8 `width` x `height`.
pub fn compare(modern: &[u8], fixed: &[u8], width: usize, height: usize) -> Report {
    let excluded = silhouettes(modern, fixed, width, height);
    let (mut compared, mut object_pixels, mut silhouette, mut differing) = (0, 0, 0, 0);
    let (mut max, mut silhouette_max, mut sum) = (0u8, 0u8, 0u64);
    for (i, &excluded) in excluded.iter().enumerate() {
        let (a, b) = (pixel(modern, i), pixel(fixed, i));
        let difference = channel_difference(a, b);
        if excluded {
            silhouette += 1;
            silhouette_max = silhouette_max.max(difference);
            continue;
        }
        compared += 1;
        max = max.max(difference);
        differing += usize::from(difference > 0);
        if a[3] != 0 || b[3] != 0 {
            object_pixels += 1;
            sum += a
                .iter()
                .zip(b)
                .map(|(x, y)| u64::from(x.abs_diff(*y)))
                .sum::<u64>();
        }
    }
    let mean = sum as f64 / (4 * object_pixels.max(1)) as f64;

    // The checks: a comparison of two empty or flat images would prove nothing.
    let mut checks = Vec::new();
    for (name, image) in [("core (fflight)", modern), ("fixed-function", fixed)] {
        for (k, &alpha) in crate::scene::OBJECT_ALPHAS.iter().enumerate().skip(1) {
            let value = (alpha * 255.0).round() as u8;
            let count = (0..width * height)
                .filter(|&i| pixel(image, i)[3] == value)
                .count();
            checks.push((
                format!("{name}: object {k} (alpha {value}) covers {count} >= 400 pixels"),
                count >= 400,
            ));
        }
        let luminance: Vec<u32> = (0..width * height)
            .map(|i| pixel(image, i))
            .filter(|p| p[3] != 0)
            .map(|p| (299 * u32::from(p[0]) + 587 * u32::from(p[1]) + 114 * u32::from(p[2])) / 1000)
            .collect();
        let range = luminance.iter().max().unwrap_or(&0) - luminance.iter().min().unwrap_or(&0);
        checks.push((
            format!("{name}: the lit objects' luminance spans {range} >= 120 steps"),
            range >= 120,
        ));
    }
    checks.push((
        format!("silhouette pixels {silhouette} <= 10% of the frame"),
        silhouette * 10 <= width * height,
    ));

    Report {
        compared,
        object_pixels,
        silhouette,
        max,
        mean,
        differing,
        silhouette_max,
        checks,
    }
}

impl Report {
    /// Ok when every check holds and the compared pixels are within the tolerance.
    pub fn verdict(&self) -> Result<(), String> {
        if let Some((check, _)) = self.checks.iter().find(|(_, holds)| !holds) {
            return Err(format!("check failed: {check}"));
        }
        if self.max > TOLERANCE {
            return Err(format!(
                "largest difference {}/255 away from silhouettes, tolerance {TOLERANCE}/255",
                self.max
            ));
        }
        Ok(())
    }
}

impl fmt::Display for Report {
    fn fmt(&self, f: &mut fmt::Formatter) -> fmt::Result {
        for (check, holds) in &self.checks {
            writeln!(
                f,
                "check: {check}: {}",
                if *holds { "ok" } else { "FAILED" }
            )?;
        }
        writeln!(
            f,
            "compared {} pixels ({} showing objects), {} silhouette pixels excluded",
            self.compared, self.object_pixels, self.silhouette
        )?;
        writeln!(
            f,
            "largest difference {}/255 (tolerance {TOLERANCE}/255), mean {:.2e}/255 per channel \
             over object pixels, {} pixels differ at all",
            self.max, self.mean, self.differing
        )?;
        writeln!(
            f,
            "on silhouettes (not held to the tolerance): largest difference {}/255",
            self.silhouette_max
        )?;
        writeln!(
            f,
            "{}",
            if self.verdict().is_ok() {
                "PASS"
            } else {
                "FAIL"
            }
        )
    }
}

/// Writes the fflight rendering, the fixed-function rendering and their difference (each
/// channel's |difference| times AMPLIFY; silhouette pixels dark blue-gray) side by side as an
/// RGB PNG.
pub fn write_png(
    path: &str,
    modern: &[u8],
    fixed: &[u8],
    width: usize,
    height: usize,
) -> Result<(), String> {
    let excluded = silhouettes(modern, fixed, width, height);
    let mut rgb = Vec::with_capacity(3 * width * 3 * height);
    // glReadPixels rows run bottom to top, PNG rows top to bottom.
    for y in (0..height).rev() {
        for image in [modern, fixed] {
            for x in 0..width {
                rgb.extend_from_slice(&pixel(image, y * width + x)[..3]);
            }
        }
        for x in 0..width {
            let i = y * width + x;
            if excluded[i] {
                rgb.extend_from_slice(&[40, 40, 64]);
            } else {
                let (a, b) = (pixel(modern, i), pixel(fixed, i));
                for c in 0..3 {
                    rgb.push(a[c].abs_diff(b[c]).saturating_mul(AMPLIFY));
                }
            }
        }
    }
    let file = std::fs::File::create(path).map_err(|e| format!("{path}: {e}"))?;
    let mut encoder = png::Encoder::new(
        std::io::BufWriter::new(file),
        3 * width as u32,
        height as u32,
    );
    encoder.set_color(png::ColorType::Rgb);
    encoder.set_depth(png::BitDepth::Eight);
    let mut writer = encoder.write_header().map_err(|e| format!("{path}: {e}"))?;
    writer
        .write_image_data(&rgb)
        .map_err(|e| format!("{path}: {e}"))?;
    writer.finish().map_err(|e| format!("{path}: {e}"))
}
