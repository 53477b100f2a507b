//! Pictures a person can judge a clustering by: the range image coloured by
//! cluster (with the ground truth under it when known) and a bird's-eye
//! view, in one PNG.
//!
//! Colours: each cluster gets a hue from its id (golden-ratio steps, so
//! neighbouring ids differ); ground-truth instances take the colour of the
//! cluster that overlaps them most, so a correct clustering shows the same
//! colours in both panels and a wrong one shows where it splits or merges.
//! Ground is dark brown, points in no cluster grey, empty pixels black;
//! range darkens colours a little so shapes stay visible.

use crate::error::{LidarError, Result};
use crate::image::{norm, RangeImage};
use std::collections::HashMap;
use std::io::BufWriter;
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

/// The colour of cluster `label` (0: grey).
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
        let file = std::fs::File::create(path).map_err(|e| LidarError::io(path, e))?;
        let (w, h) = (
            u32::try_from(self.width).map_err(|_| LidarError::Config("picture too wide".into()))?,
            u32::try_from(self.height)
                .map_err(|_| LidarError::Config("picture too tall".into()))?,
        );
        let mut enc = png::Encoder::new(BufWriter::new(file), w, h);
        enc.set_color(png::ColorType::Rgb);
        enc.set_depth(png::BitDepth::Eight);
        let png_err =
            |e: png::EncodingError| LidarError::malformed(path, format!("writing PNG: {e}"));
        let mut writer = enc.write_header().map_err(png_err)?;
        writer.write_image_data(&self.rgb).map_err(png_err)?;
        writer.finish().map_err(png_err)
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
fn truth_colours(labels: &[u32], truth: &[u32]) -> HashMap<u32, [u8; 3]> {
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
        .map(|(t, (_, l))| (t, cluster_colour(l)))
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

/// A bird's-eye view `size` pixels square covering `extent_m` metres on
/// each side of the sensor: +x up, +y left, rings every 10 m.
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
    let mut ring = 10.0f32;
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
        ring += 10.0;
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
    // The sensor.
    for d in -3i64..=3 {
        pic.put(half as i64 + d, half as i64, TEXT);
        pic.put(half as i64, half as i64 + d, TEXT);
    }
    pic
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
    let bev = if o.truth.is_some() {
        width / 2
    } else {
        width.min(1024)
    };
    let range_h = o.image.rows * scale;
    let panels = if o.truth.is_some() { 2 } else { 1 };
    let height = panels * (caption + range_h) + caption + bev;
    let mut pic = Picture::new(width, height, BACKGROUND);
    let mut y = 0;
    pic.text(6, y + 6, &o.title, text_scale, TEXT);
    y += caption;
    pic.blit(&range_panel(o.image, o.labels, o.ground, None, scale), 0, y);
    y += range_h;
    let truth_colours = o.truth.map(|t| truth_colours(o.labels, t));
    if let Some(t) = o.truth {
        pic.text(6, y + 6, &o.truth_title, text_scale, TEXT);
        y += caption;
        pic.blit(
            &range_panel(o.image, t, o.ground, truth_colours.as_ref(), scale),
            0,
            y,
        );
        y += range_h;
    }
    pic.text(6, y + 6, "BIRD'S-EYE VIEW: CLUSTERS", text_scale, TEXT);
    if o.truth.is_some() {
        pic.text(
            bev + 6,
            y + 6,
            "BIRD'S-EYE VIEW: GROUND TRUTH",
            text_scale,
            TEXT,
        );
    }
    y += caption;
    pic.blit(
        &bev_panel(o.image, o.labels, o.ground, None, o.bev_extent_m, bev),
        0,
        y,
    );
    if let Some(t) = o.truth {
        pic.blit(
            &bev_panel(
                o.image,
                t,
                o.ground,
                truth_colours.as_ref(),
                o.bev_extent_m,
                bev,
            ),
            bev,
            y,
        );
    }
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
        let c = truth_colours(&labels, &truth);
        assert_eq!(c[&5], cluster_colour(1));
        assert_eq!(c[&9], cluster_colour(2));
        assert!(c.contains_key(&7));
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
        let caption = 27;
        assert_eq!(pic.height, 2 * (caption + 8) + caption + 512);
        // The clustered pixel (row 0, col 5) shows its cluster's colour, shaded,
        // on both picture rows of its image row.
        assert_eq!(pic.get(5, caption), shade(cluster_colour(1), 10.0));
        assert_eq!(pic.get(5, caption + 1), shade(cluster_colour(1), 10.0));
        assert_eq!(pic.get(6, caption), shade(UNCLUSTERED, 50f32.sqrt()));
        assert_eq!(pic.get(7, caption), EMPTY);
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
