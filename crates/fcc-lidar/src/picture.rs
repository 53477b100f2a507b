//! Pictures a person can judge a clustering by, without the docs: a caption,
//! a colour key, the range image coloured by cluster with azimuth ticks (with
//! the ground truth under it when known), and bird's-eye views with numbered
//! range rings and x/y arrows: clusters beside the ground truth, or beside
//! the ground removal when there is no ground truth, in one PNG.
//!
//! Colours: clusters that touch in the range image get different colours of
//! a palette ([`cluster_colours`]); ground-truth instances take the colour of
//! the cluster that overlaps them most, so a correct clustering shows the same
//! colours in both panels and a wrong one shows where it splits or merges.
//! Ground is brown, points in no cluster grey, empty pixels black; range
//! darkens colours a little so shapes stay visible.

use crate::error::{LidarError, Result};
use crate::image::{norm, RangeImage};
use std::collections::HashMap;
use std::path::Path;

/// An RGB picture.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Picture {
    pub width: usize,
    pub height: usize,
    /// `width * height * 3` bytes, row-major.
    pub rgb: Vec<u8>,
}

const EMPTY: [u8; 3] = [0, 0, 0];
const GROUND: [u8; 3] = [110, 80, 50];
const UNCLUSTERED: [u8; 3] = [150, 150, 150];
const TEXT: [u8; 3] = [235, 235, 235];
const BACKGROUND: [u8; 3] = [24, 24, 32];

/// Well-separated colours for clusters (none close to the ground, grey or
/// black of the key).
const PALETTE: [[u8; 3]; 12] = [
    [230, 25, 75],
    [60, 180, 75],
    [255, 225, 25],
    [67, 99, 216],
    [245, 130, 49],
    [145, 30, 180],
    [66, 212, 244],
    [240, 50, 230],
    [191, 239, 69],
    [250, 190, 212],
    [0, 128, 128],
    [220, 190, 255],
];

/// A colour per cluster such that clusters touching in the range image (within
/// two columns or one row) differ clearly: greedy colouring in label order
/// from [`PALETTE`], each cluster taking the colour furthest (in RGB) from
/// those of its already coloured neighbours; ties go to the colour at its own
/// id, so clusters far apart still vary.
pub fn cluster_colours(rows: usize, cols: usize, labels: &[u32]) -> HashMap<u32, [u8; 3]> {
    let mut adj: HashMap<u32, Vec<u32>> = HashMap::new();
    let mut link = |a: u32, b: u32| {
        if a != 0 && b != 0 && a != b {
            adj.entry(a).or_default().push(b);
            adj.entry(b).or_default().push(a);
        }
    };
    for r in 0..rows {
        for c in 0..cols {
            let a = labels[r * cols + c];
            if a == 0 {
                continue;
            }
            for dc in 1..=2 {
                link(a, labels[r * cols + (c + dc) % cols]);
            }
            if r + 1 < rows {
                for dc in [cols - 1, 0, 1] {
                    link(a, labels[(r + 1) * cols + (c + dc) % cols]);
                }
            }
        }
    }
    let mut ids: Vec<u32> = labels.iter().copied().filter(|&l| l != 0).collect();
    ids.sort_unstable();
    ids.dedup();
    let dist = |a: [u8; 3], b: [u8; 3]| -> i32 {
        (0..3)
            .map(|k| (i32::from(a[k]) - i32::from(b[k])).abs())
            .sum()
    };
    let mut out: HashMap<u32, usize> = HashMap::new();
    for id in ids {
        let near: Vec<[u8; 3]> = adj
            .get(&id)
            .map(Vec::as_slice)
            .unwrap_or_default()
            .iter()
            .filter_map(|n| out.get(n).map(|&k| PALETTE[k]))
            .collect();
        let start = id as usize % PALETTE.len();
        let mut pick = start;
        let mut best = i32::MIN;
        for k in (0..PALETTE.len()).map(|k| (start + k) % PALETTE.len()) {
            let score = near
                .iter()
                .map(|&c| dist(c, PALETTE[k]))
                .min()
                .unwrap_or(i32::MAX);
            if score > best {
                best = score;
                pick = k;
            }
        }
        out.insert(id, pick);
    }
    out.into_iter().map(|(id, k)| (id, PALETTE[k])).collect()
}

/// A colour from the id alone (0: grey), for a cluster with no neighbours
/// known (see [`cluster_colours`] for pictures).
pub fn cluster_colour(label: u32) -> [u8; 3] {
    if label == 0 {
        return UNCLUSTERED;
    }
    let h = (f64::from(label) * 0.618_033_988_749_895).fract() * 6.0;
    let (s, v) = (0.75, 1.0);
    let c = v * s;
    let x = c * (1.0 - ((h % 2.0) - 1.0).abs());
    let m = v - c;
    let (r, g, b) = match h as u32 {
        0 => (c, x, 0.0),
        1 => (x, c, 0.0),
        2 => (0.0, c, x),
        3 => (0.0, x, c),
        4 => (x, 0.0, c),
        _ => (c, 0.0, x),
    };
    [
        ((r + m) * 255.0) as u8,
        ((g + m) * 255.0) as u8,
        ((b + m) * 255.0) as u8,
    ]
}

fn shade(c: [u8; 3], range: f32) -> [u8; 3] {
    let k = 1.0 - 0.45 * (range / 60.0).clamp(0.0, 1.0);
    [
        (f32::from(c[0]) * k) as u8,
        (f32::from(c[1]) * k) as u8,
        (f32::from(c[2]) * k) as u8,
    ]
}

impl Picture {
    /// A picture filled with one colour.
    pub fn new(width: usize, height: usize, fill: [u8; 3]) -> Picture {
        Picture {
            width,
            height,
            rgb: fill
                .iter()
                .copied()
                .cycle()
                .take(width * height * 3)
                .collect(),
        }
    }

    /// Set one pixel (ignored outside the picture).
    pub fn put(&mut self, x: i64, y: i64, c: [u8; 3]) {
        if x >= 0 && y >= 0 && (x as usize) < self.width && (y as usize) < self.height {
            let i = 3 * (y as usize * self.width + x as usize);
            self.rgb[i..i + 3].copy_from_slice(&c);
        }
    }

    /// The colour at (x, y).
    pub fn get(&self, x: usize, y: usize) -> [u8; 3] {
        let i = 3 * (y * self.width + x);
        [self.rgb[i], self.rgb[i + 1], self.rgb[i + 2]]
    }

    /// Copy another picture in with its top-left corner at (x, y).
    pub fn blit(&mut self, other: &Picture, x: usize, y: usize) {
        for oy in 0..other.height {
            for ox in 0..other.width {
                self.put((x + ox) as i64, (y + oy) as i64, other.get(ox, oy));
            }
        }
    }

    /// Write `text` (upper-case letters, digits, common signs) at (x, y)
    /// with a 3 x 5 font scaled by `scale`.
    pub fn text(&mut self, x: usize, y: usize, text: &str, scale: usize, c: [u8; 3]) {
        let mut cx = x;
        for ch in text.chars() {
            let g = glyph(ch.to_ascii_uppercase());
            for (row, bits) in g.iter().enumerate() {
                for col in 0..3 {
                    if bits.as_bytes()[col] == b'#' {
                        for dy in 0..scale {
                            for dx in 0..scale {
                                self.put(
                                    (cx + col * scale + dx) as i64,
                                    (y + row * scale + dy) as i64,
                                    c,
                                );
                            }
                        }
                    }
                }
            }
            cx += 4 * scale;
        }
    }

    /// Save as an 8-bit RGB PNG.
    pub fn save_png(&self, path: &Path) -> Result<()> {
        let mut file = fcc_io::AtomicFile::create(path).map_err(|e| LidarError::io(path, e))?;
        let (w, h) = (
            u32::try_from(self.width).map_err(|_| LidarError::Config("picture too wide".into()))?,
            u32::try_from(self.height)
                .map_err(|_| LidarError::Config("picture too tall".into()))?,
        );
        let mut enc = png::Encoder::new(&mut file, w, h);
        enc.set_color(png::ColorType::Rgb);
        enc.set_depth(png::BitDepth::Eight);
        let png_err =
            |e: png::EncodingError| LidarError::malformed(path, format!("writing PNG: {e}"));
        let mut writer = enc.write_header().map_err(png_err)?;
        writer.write_image_data(&self.rgb).map_err(png_err)?;
        writer.finish().map_err(png_err)?;
        file.commit().map_err(|e| LidarError::io(path, e))
    }
}

fn glyph(c: char) -> [&'static str; 5] {
    match c {
        '0' => ["###", "#.#", "#.#", "#.#", "###"],
        '1' => [".#.", "##.", ".#.", ".#.", "###"],
        '2' => ["###", "..#", "###", "#..", "###"],
        '3' => ["###", "..#", ".##", "..#", "###"],
        '4' => ["#.#", "#.#", "###", "..#", "..#"],
        '5' => ["###", "#..", "###", "..#", "###"],
        '6' => ["###", "#..", "###", "#.#", "###"],
        '7' => ["###", "..#", ".#.", ".#.", ".#."],
        '8' => ["###", "#.#", "###", "#.#", "###"],
        '9' => ["###", "#.#", "###", "..#", "###"],
        'A' => [".#.", "#.#", "###", "#.#", "#.#"],
        'B' => ["##.", "#.#", "##.", "#.#", "##."],
        'C' => [".##", "#..", "#..", "#..", ".##"],
        'D' => ["##.", "#.#", "#.#", "#.#", "##."],
        'E' => ["###", "#..", "##.", "#..", "###"],
        'F' => ["###", "#..", "##.", "#..", "#.."],
        'G' => [".##", "#..", "#.#", "#.#", ".##"],
        'H' => ["#.#", "#.#", "###", "#.#", "#.#"],
        'I' => ["###", ".#.", ".#.", ".#.", "###"],
        'J' => ["..#", "..#", "..#", "#.#", ".#."],
        'K' => ["#.#", "#.#", "##.", "#.#", "#.#"],
        'L' => ["#..", "#..", "#..", "#..", "###"],
        'M' => ["#.#", "###", "#.#", "#.#", "#.#"],
        'N' => ["##.", "#.#", "#.#", "#.#", "#.#"],
        'O' => [".#.", "#.#", "#.#", "#.#", ".#."],
        'P' => ["##.", "#.#", "##.", "#..", "#.."],
        'Q' => [".#.", "#.#", "#.#", "##.", ".##"],
        'R' => ["##.", "#.#", "##.", "#.#", "#.#"],
        'S' => [".##", "#..", ".#.", "..#", "##."],
        'T' => ["###", ".#.", ".#.", ".#.", ".#."],
        'U' => ["#.#", "#.#", "#.#", "#.#", "###"],
        'V' => ["#.#", "#.#", "#.#", "#.#", ".#."],
        'W' => ["#.#", "#.#", "#.#", "###", "#.#"],
        'X' => ["#.#", "#.#", ".#.", "#.#", "#.#"],
        'Y' => ["#.#", "#.#", ".#.", ".#.", ".#."],
        'Z' => ["###", "..#", ".#.", "#..", "###"],
        '=' => ["...", "###", "...", "###", "..."],
        ':' => ["...", ".#.", "...", ".#.", "..."],
        '.' => ["...", "...", "...", "...", ".#."],
        ',' => ["...", "...", "...", ".#.", "#.."],
        '-' => ["...", "...", "###", "...", "..."],
        '+' => ["...", ".#.", "###", ".#.", "..."],
        '/' => ["..#", "..#", ".#.", "#..", "#.."],
        '(' => [".#.", "#..", "#..", "#..", ".#."],
        ')' => [".#.", "..#", "..#", "..#", ".#."],
        '%' => ["#.#", "..#", ".#.", "#..", "#.#"],
        '<' => ["..#", ".#.", "#..", ".#.", "..#"],
        '>' => ["#..", ".#.", "..#", ".#.", "#.."],
        '_' => ["...", "...", "...", "...", "###"],
        '\'' => [".#.", ".#.", "...", "...", "..."],
        _ => ["...", "...", "...", "...", "..."],
    }
}

/// Colours for ground-truth instances: the colour of the cluster overlapping
/// each instance most.
fn truth_colours(
    labels: &[u32],
    truth: &[u32],
    clusters: &HashMap<u32, [u8; 3]>,
) -> HashMap<u32, [u8; 3]> {
    let mut overlap: HashMap<(u32, u32), usize> = HashMap::new();
    for (&t, &l) in truth.iter().zip(labels) {
        if t != 0 && l != 0 {
            *overlap.entry((t, l)).or_insert(0) += 1;
        }
    }
    let mut best: HashMap<u32, (usize, u32)> = HashMap::new();
    for (&(t, l), &n) in &overlap {
        let e = best.entry(t).or_insert((0, 0));
        if n > e.0 || (n == e.0 && l < e.1) {
            *e = (n, l);
        }
    }
    let mut out: HashMap<u32, [u8; 3]> = best
        .into_iter()
        .map(|(t, (_, l))| {
            (
                t,
                clusters
                    .get(&l)
                    .copied()
                    .unwrap_or_else(|| cluster_colour(l)),
            )
        })
        .collect();
    for &t in truth {
        if t != 0 {
            out.entry(t)
                .or_insert_with(|| cluster_colour(t.wrapping_mul(7919).wrapping_add(13)));
        }
    }
    out
}

/// The colour of one pixel.
fn pixel_colour(
    image: &RangeImage,
    i: usize,
    label: u32,
    ground: bool,
    colours: Option<&HashMap<u32, [u8; 3]>>,
) -> Option<[u8; 3]> {
    let p = image.point(i)?;
    let base = if label != 0 {
        colours
            .and_then(|m| m.get(&label).copied())
            .unwrap_or_else(|| cluster_colour(label))
    } else if ground {
        GROUND
    } else {
        UNCLUSTERED
    };
    Some(shade(base, norm(p)))
}

/// How tall a range-image row is drawn so the image is not a thin strip.
pub fn row_scale(rows: usize, cols: usize) -> usize {
    (cols / (rows.max(1) * 8)).clamp(2, 8)
}

/// The range image, one picture pixel per image pixel horizontally and
/// `row_scale` vertically.
pub fn range_panel(
    image: &RangeImage,
    labels: &[u32],
    ground: Option<&[bool]>,
    colours: Option<&HashMap<u32, [u8; 3]>>,
    row_scale: usize,
) -> Picture {
    let mut pic = Picture::new(image.cols, image.rows * row_scale, EMPTY);
    for r in 0..image.rows {
        for c in 0..image.cols {
            let i = r * image.cols + c;
            let g = ground.is_some_and(|g| g[i]);
            if let Some(col) = pixel_colour(image, i, labels[i], g, colours) {
                for k in 0..row_scale {
                    pic.put(c as i64, (r * row_scale + k) as i64, col);
                }
            }
        }
    }
    pic
}

/// The spacing of the range rings for a half-width of `extent_m`: 10 m, or
/// 20 m beyond 40 m so the numbers stay readable.
pub fn ring_step_m(extent_m: f32) -> f32 {
    if extent_m > 40.0 {
        20.0
    } else {
        10.0
    }
}

/// A bird's-eye view `size` pixels square covering `extent_m` metres on
/// each side of the sensor: +x up, +y left (arrows at the sensor), range
/// rings numbered in metres.
pub fn bev_panel(
    image: &RangeImage,
    labels: &[u32],
    ground: Option<&[bool]>,
    colours: Option<&HashMap<u32, [u8; 3]>>,
    extent_m: f32,
    size: usize,
) -> Picture {
    let mut pic = Picture::new(size, size, EMPTY);
    let res = 2.0 * extent_m / size as f32;
    let half = size as f32 / 2.0;
    // Range rings.
    let step = ring_step_m(extent_m);
    let mut ring = step;
    while ring <= extent_m * 1.5 {
        let steps = (ring / res * 8.0) as usize + 8;
        for k in 0..steps {
            let a = std::f32::consts::TAU * k as f32 / steps as f32;
            pic.put(
                (half + ring / res * a.cos()) as i64,
                (half + ring / res * a.sin()) as i64,
                [45, 45, 55],
            );
        }
        ring += step;
    }
    // Ground and unclustered first, clusters over them.
    for pass in 0..2 {
        for i in 0..image.pixels() {
            let Some(p) = image.point(i) else {
                continue;
            };
            let l = labels[i];
            if (pass == 0) != (l == 0) {
                continue;
            }
            let g = ground.is_some_and(|g| g[i]);
            let Some(col) = pixel_colour(image, i, l, g, colours) else {
                continue;
            };
            let x = half - p[1] / res;
            let y = half - p[0] / res;
            let dot = if l == 0 { 1 } else { 2 };
            for dy in 0..dot {
                for dx in 0..dot {
                    pic.put(x as i64 + dx, y as i64 + dy, col);
                }
            }
        }
    }
    // Ring numbers, along the diagonal to the lower right (behind-right of
    // the sensor), over the points.
    let mut ring = step;
    while ring < extent_m * 1.42 {
        let d = ring / res * std::f32::consts::FRAC_1_SQRT_2;
        let (x, y) = ((half + d) as i64 + 2, (half + d) as i64 + 2);
        if x >= 0 && y >= 0 {
            pic.text(x as usize, y as usize, &format!("{ring:.0} M"), 2, TEXT);
        }
        ring += step;
    }
    // The sensor, and arrows for +x (up) and +y (left).
    let (cx, cy) = (half as i64, half as i64);
    let len = (size as i64 / 12).max(12);
    for d in 0..=len {
        pic.put(cx, cy - d, TEXT);
        pic.put(cx - d, cy, TEXT);
    }
    for k in 1..=4 {
        pic.put(cx - k, cy - len + k, TEXT);
        pic.put(cx + k, cy - len + k, TEXT);
        pic.put(cx - len + k, cy - k, TEXT);
        pic.put(cx - len + k, cy + k, TEXT);
    }
    if cy - len - 14 >= 0 && cx - len - 12 >= 0 {
        pic.text((cx - 2) as usize, (cy - len - 14) as usize, "X", 2, TEXT);
        pic.text((cx - len - 12) as usize, (cy - 5) as usize, "Y", 2, TEXT);
    }
    pic
}

/// Azimuth of each column, degrees (atan2(y, x), 0 ahead, +90 left), from
/// the mean direction of its points; `None` for a column with no point.
pub fn column_azimuths(image: &RangeImage) -> Vec<Option<f64>> {
    (0..image.cols)
        .map(|c| {
            let (mut sx, mut sy) = (0.0f64, 0.0f64);
            for r in 0..image.rows {
                if let Some(p) = image.point(r * image.cols + c) {
                    let n = f64::from(p[0]).hypot(f64::from(p[1]));
                    if n > 0.0 {
                        sx += f64::from(p[0]) / n;
                        sy += f64::from(p[1]) / n;
                    }
                }
            }
            (sx != 0.0 || sy != 0.0).then(|| sy.atan2(sx).to_degrees())
        })
        .collect()
}

/// Where the azimuth crosses a multiple of 90 degrees: (column, degrees),
/// found from the data, so the ticks are right for any column convention.
pub fn azimuth_ticks(image: &RangeImage) -> Vec<(usize, i32)> {
    let az = column_azimuths(image);
    let mut ticks: Vec<(usize, i32)> = Vec::new();
    let mut prev: Option<(usize, f64)> = None;
    for (c, a) in az.iter().enumerate() {
        let Some(a) = *a else { continue };
        if let Some((_, p)) = prev {
            // Unwrapped step from p to a, less than 90 degrees between columns
            // that hold points.
            let mut step = a - p;
            if step > 180.0 {
                step -= 360.0;
            } else if step < -180.0 {
                step += 360.0;
            }
            if step.abs() < 90.0 {
                for t in [-180i32, -90, 0, 90, 180] {
                    let t = f64::from(t);
                    let crossed = (p < t && p + step >= t) || (p > t && p + step <= t);
                    // The +-180 seam: a step across it crosses 180.
                    let seam = t == 180.0 && (p + step > 180.0 || p + step < -180.0);
                    if crossed || seam {
                        let deg = if t == -180.0 { 180 } else { t as i32 };
                        let repeat =
                            matches!(ticks.last(), Some(&(lc, ld)) if ld == deg && c <= lc + 8);
                        if !repeat {
                            ticks.push((c, deg));
                        }
                    }
                }
            }
        }
        prev = Some((c, a));
    }
    ticks
}

/// A strip `height` pixels high and `width` wide with a tick and the azimuth
/// in degrees at each crossing of a multiple of 90 degrees.
fn azimuth_strip(image: &RangeImage, width: usize, height: usize) -> Picture {
    let mut pic = Picture::new(width, height, BACKGROUND);
    for (c, deg) in azimuth_ticks(image) {
        let x = (c * width / image.cols.max(1)) as i64;
        for y in (height as i64 - 4)..height as i64 {
            pic.put(x, y, TEXT);
        }
        let text = format!("{deg}");
        let w = 8 * text.len() as i64;
        let tx = (x - w / 2).clamp(0, width as i64 - w).max(0) as usize;
        pic.text(tx, 1, &text, 2, TEXT);
    }
    pic
}

/// The largest text scale up to `max` at which `text` fits in `width` pixels
/// (at least 1: a longer text is cut at the edge).
pub fn fit_scale(text: &str, width: usize, max: usize) -> usize {
    let chars = text.chars().count().max(1);
    (1..=max)
        .rev()
        .find(|s| 4 * s * chars <= width)
        .unwrap_or(1)
}

/// The colour key: a swatch and a word for ground, points in no cluster and
/// empty pixels.
fn colour_key(pic: &mut Picture, x: usize, y: usize, scale: usize) {
    let mut cx = x;
    for (c, word) in [
        (GROUND, "GROUND"),
        (UNCLUSTERED, "NO CLUSTER"),
        (EMPTY, "EMPTY"),
        (PALETTE[0], "CLUSTERS: ANY OTHER COLOUR"),
    ] {
        let s = 5 * scale;
        for dy in 0..s {
            for dx in 0..s {
                pic.put((cx + dx) as i64, (y + dy) as i64, c);
            }
        }
        // A light border so the black swatch shows.
        for d in 0..s {
            for (px, py) in [
                (cx + d, y),
                (cx + d, y + s - 1),
                (cx, y + d),
                (cx + s - 1, y + d),
            ] {
                pic.put(px as i64, py as i64, [90, 90, 100]);
            }
        }
        pic.text(cx + s + 2 * scale, y, word, scale, TEXT);
        cx += s + 2 * scale + 4 * scale * word.len() + 6 * scale;
    }
}

/// What goes into an overview picture.
#[derive(Debug, Clone)]
pub struct Overview<'a> {
    pub image: &'a RangeImage,
    /// Cluster label per pixel (0: none).
    pub labels: &'a [u32],
    /// Ground pixels, if ground removal ran.
    pub ground: Option<&'a [bool]>,
    /// Ground-truth instance per pixel, if known.
    pub truth: Option<&'a [u32]>,
    /// Caption over the clustering.
    pub title: String,
    /// Caption over the ground truth.
    pub truth_title: String,
    /// Half-width of the bird's-eye view, metres.
    pub bev_extent_m: f32,
}

/// One picture: caption, range image by cluster, the same for the ground
/// truth when known, and the bird's-eye views side by side under them.
pub fn render_overview(o: &Overview<'_>) -> Result<Picture> {
    let n = o.image.pixels();
    let check = |what: &str, len: usize| {
        if len == n {
            Ok(())
        } else {
            Err(LidarError::Mismatch {
                what: format!("{what} of a {} x {} picture", o.image.rows, o.image.cols),
                expected: n,
                got: len,
            })
        }
    };
    check("labels", o.labels.len())?;
    if let Some(g) = o.ground {
        check("ground flags", g.len())?;
    }
    if let Some(t) = o.truth {
        check("ground truth", t.len())?;
    }
    if !(o.bev_extent_m.is_finite() && o.bev_extent_m > 0.0) {
        return Err(LidarError::Config(format!(
            "bird's-eye extent {} m must be positive",
            o.bev_extent_m
        )));
    }
    let scale = row_scale(o.image.rows, o.image.cols);
    let width = o.image.cols.max(1024);
    let text_scale = 3;
    let caption = 5 * text_scale + 12;
    let key_h = 5 * 2 + 8;
    let ticks_h = 5 * 2 + 6;
    // Two bird's-eye views side by side: clusters, and the ground truth or,
    // without one, the ground removal.
    let bev = width / 2;
    let range_h = o.image.rows * scale;
    let panels = if o.truth.is_some() { 2 } else { 1 };
    let height = key_h + panels * (caption + ticks_h + range_h) + caption + bev;
    let mut pic = Picture::new(width, height, BACKGROUND);
    let clusters = cluster_colours(o.image.rows, o.image.cols, o.labels);
    let mut y = 0;
    pic.text(
        6,
        y + 6,
        &o.title,
        fit_scale(&o.title, width - 12, text_scale),
        TEXT,
    );
    y += caption;
    colour_key(&mut pic, 6, y + 2, 2);
    y += key_h;
    let strip = azimuth_strip(o.image, o.image.cols, ticks_h);
    pic.blit(&strip, 0, y);
    y += ticks_h;
    pic.blit(
        &range_panel(o.image, o.labels, o.ground, Some(&clusters), scale),
        0,
        y,
    );
    y += range_h;
    let truth_colours = o.truth.map(|t| truth_colours(o.labels, t, &clusters));
    if let Some(t) = o.truth {
        let s = fit_scale(&o.truth_title, width - 12, text_scale);
        pic.text(6, y + 6, &o.truth_title, s, TEXT);
        y += caption;
        pic.blit(&strip, 0, y);
        y += ticks_h;
        pic.blit(
            &range_panel(o.image, t, o.ground, truth_colours.as_ref(), scale),
            0,
            y,
        );
        y += range_h;
    }
    pic.text(6, y + 6, "BIRD'S-EYE VIEW: CLUSTERS", text_scale, TEXT);
    let right_title = match (o.truth.is_some(), o.ground.is_some()) {
        (true, _) => "BIRD'S-EYE VIEW: GROUND TRUTH",
        (false, true) => "GROUND REMOVAL: GROUND BROWN, KEPT GREY",
        (false, false) => "GROUND REMOVAL: NONE (ALL KEPT)",
    };
    pic.text(bev + 6, y + 6, right_title, text_scale, TEXT);
    y += caption;
    pic.blit(
        &bev_panel(
            o.image,
            o.labels,
            o.ground,
            Some(&clusters),
            o.bev_extent_m,
            bev,
        ),
        0,
        y,
    );
    let right = match o.truth {
        Some(t) => bev_panel(
            o.image,
            t,
            o.ground,
            truth_colours.as_ref(),
            o.bev_extent_m,
            bev,
        ),
        // Every point unlabelled: ground shows brown, the rest grey.
        None => bev_panel(
            o.image,
            &vec![0; o.image.pixels()],
            o.ground,
            None,
            o.bev_extent_m,
            bev,
        ),
    };
    pic.blit(&right, bev, y);
    Ok(pic)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn colours_differ_for_neighbouring_ids_and_zero_is_grey() {
        assert_eq!(cluster_colour(0), UNCLUSTERED);
        for l in 1..200u32 {
            assert_ne!(cluster_colour(l), cluster_colour(l + 1));
        }
    }

    #[test]
    fn truth_takes_the_colour_of_its_best_cluster() {
        let labels = [1, 1, 2, 2, 2, 0];
        let truth = [5, 5, 5, 9, 9, 7];
        let clusters = cluster_colours(1, 6, &labels);
        let c = truth_colours(&labels, &truth, &clusters);
        assert_eq!(c[&5], clusters[&1]);
        assert_eq!(c[&9], clusters[&2]);
        assert!(c.contains_key(&7));
    }

    fn far_apart(a: [u8; 3], b: [u8; 3]) -> bool {
        let d: i32 = (0..3)
            .map(|k| (i32::from(a[k]) - i32::from(b[k])).abs())
            .sum();
        d >= 120
    }

    #[test]
    fn touching_clusters_get_clearly_different_colours() {
        // Ids 1 and 22 have nearly the same golden-ratio hue.
        let labels = [1, 1, 22, 22, 0, 0, 0, 0];
        let c = cluster_colours(1, 8, &labels);
        assert!(far_apart(c[&1], c[&22]), "{:?} {:?}", c[&1], c[&22]);
        // Forty two-pixel clusters in a row, and a second row shifted by one.
        let (rows, cols) = (2, 80);
        let mut labels = vec![0u32; rows * cols];
        for i in 0..cols {
            labels[i] = 1 + i as u32 / 2;
            labels[cols + i] = 41 + ((i + 1) % cols) as u32 / 2;
        }
        let c = cluster_colours(rows, cols, &labels);
        for r in 0..rows {
            for i in 0..cols {
                let (a, b) = (labels[r * cols + i], labels[r * cols + (i + 1) % cols]);
                if a != b {
                    assert!(
                        far_apart(c[&a], c[&b]),
                        "row {r} col {i}: {a} and {b}: {:?} {:?}",
                        c[&a],
                        c[&b]
                    );
                }
                if r == 0 && a != labels[cols + i] {
                    let b = labels[cols + i];
                    assert_ne!(c[&a], c[&b], "col {i}: {a} above {b}");
                }
            }
        }
        for k in PALETTE {
            assert!(far_apart(k, GROUND) && far_apart(k, UNCLUSTERED) && far_apart(k, EMPTY));
        }
    }

    #[test]
    fn bird_eye_view_numbers_its_rings_and_draws_x_and_y_arrows() {
        let img = RangeImage::empty(4, 16);
        let size = 400;
        let pic = bev_panel(&img, &[0; 64], None, None, 20.0, size);
        let half = size / 2;
        // The 10 m ring's number starts at 45 degrees, 100 px out.
        let d = (100.0 * std::f32::consts::FRAC_1_SQRT_2) as usize + 2;
        let label: Vec<[u8; 3]> = (0..40)
            .flat_map(|dx| (0..10).map(move |dy| (dx, dy)))
            .map(|(dx, dy)| pic.get(half + d + dx, half + d + dy))
            .collect();
        assert!(label.contains(&TEXT), "no ring number");
        // Arrows: a line up (+x) and left (+y) from the sensor, with letters.
        let len = size / 12;
        assert_eq!(pic.get(half, half - len), TEXT);
        assert_eq!(pic.get(half - len, half), TEXT);
        assert_eq!(pic.get(half + len, half), EMPTY, "nothing to the right");
        assert_eq!(ring_step_m(80.0), 20.0);
    }

    #[test]
    fn long_captions_shrink_to_fit_the_picture() {
        assert_eq!(fit_scale("SHORT", 1012, 3), 3);
        let long = "X".repeat(100);
        assert_eq!(fit_scale(&long, 1012, 3), 2);
        assert_eq!(fit_scale(&"X".repeat(300), 1012, 3), 1);
    }

    #[test]
    fn azimuth_ticks_come_from_the_points() {
        // The projection convention: column 0 looks backwards, cols / 2 ahead,
        // columns run clockwise seen from above.
        let cols = 360;
        let mut img = RangeImage::empty(1, cols);
        for c in 0..cols {
            let a = std::f32::consts::PI - std::f32::consts::TAU * (c as f32 + 0.5) / cols as f32;
            img.set(c, Some([10.0 * a.cos(), 10.0 * a.sin(), 0.0]));
        }
        let ticks = azimuth_ticks(&img);
        let degs: Vec<i32> = ticks.iter().map(|t| t.1).collect();
        assert_eq!(degs, [90, 0, -90], "{ticks:?}");
        assert!(
            ticks.iter().any(|&(c, d)| d == 0 && c.abs_diff(180) <= 1),
            "{ticks:?}"
        );
        assert!(
            ticks.iter().any(|&(c, d)| d == 90 && c.abs_diff(90) <= 1),
            "{ticks:?}"
        );
        // Reversed columns give reversed ticks, and the seam at 180 shows.
        let mut rev = RangeImage::empty(1, cols);
        for c in 0..cols {
            rev.set(c, img.point(cols - 1 - c));
        }
        rev.set(0, None);
        let mut shifted = RangeImage::empty(1, cols);
        for c in 0..cols {
            shifted.set(c, rev.point((c + 180) % cols));
        }
        let degs: Vec<i32> = azimuth_ticks(&shifted).iter().map(|t| t.1).collect();
        assert!(degs.contains(&180), "{degs:?}");
    }

    #[test]
    fn overview_layout_and_png() {
        let mut img = RangeImage::empty(4, 16);
        img.set(5, Some([10.0, 0.0, 0.0]));
        img.set(6, Some([-5.0, 5.0, 0.0]));
        let mut labels = vec![0; 64];
        labels[5] = 1;
        let truth = vec![0; 64];
        let o = Overview {
            image: &img,
            labels: &labels,
            ground: None,
            truth: Some(&truth),
            title: "FCC K=7: 1 CLUSTER".into(),
            truth_title: "GROUND TRUTH".into(),
            bev_extent_m: 20.0,
        };
        let pic = render_overview(&o).unwrap();
        assert_eq!(pic.width, 1024);
        let (caption, key, ticks) = (27, 18, 16);
        assert_eq!(pic.height, key + 2 * (caption + ticks + 8) + caption + 512);
        // The colour key under the caption starts with the ground swatch.
        assert_eq!(pic.get(6 + 3, caption + 2 + 3), GROUND);
        // The clustered pixel (row 0, col 5) shows its cluster's colour, shaded,
        // on both picture rows of its image row.
        let top = caption + key + ticks;
        let c1 = cluster_colours(4, 16, &labels)[&1];
        assert_eq!(pic.get(5, top), shade(c1, 10.0));
        assert_eq!(pic.get(5, top + 1), shade(c1, 10.0));
        assert_eq!(pic.get(6, top), shade(UNCLUSTERED, 50f32.sqrt()));
        assert_eq!(pic.get(7, top), EMPTY);
        // Without ground truth there is no empty half: the right bird's-eye
        // view shows the ground removal (the ground point brown).
        let ground: Vec<bool> = (0..64).map(|i| i == 6).collect();
        let no_truth = Overview {
            truth: None,
            ground: Some(&ground),
            ..o.clone()
        };
        let pic = render_overview(&no_truth).unwrap();
        assert_eq!(pic.height, key + caption + ticks + 8 + caption + 512);
        let bev_top = key + caption + ticks + 8 + caption;
        let right: Vec<[u8; 3]> = (0..512)
            .flat_map(|y| (512..1024).map(move |x| (x, y)))
            .map(|(x, y)| pic.get(x, bev_top + y))
            .collect();
        assert!(
            right.contains(&shade(GROUND, 50f32.sqrt())),
            "no ground in the right panel"
        );
        let dir = tempfile::tempdir().unwrap();
        let p = dir.path().join("o.png");
        pic.save_png(&p).unwrap();
        let bytes = std::fs::read(&p).unwrap();
        assert_eq!(&bytes[1..4], b"PNG");
        let bad = Overview {
            labels: &labels[..3],
            ..o.clone()
        };
        assert!(render_overview(&bad)
            .unwrap_err()
            .to_string()
            .contains("labels of a 4 x 16 picture"));
    }
}
