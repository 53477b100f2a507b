//! The bare-metal C example written beside every block design compiles as
//! C99 with every warning an error against minimal stand-ins of the Xilinx
//! headers it includes (`tests/xilinx_stub`), and its quantisation packs
//! pixels exactly as the golden model does.

use std::io::Write;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};

use fcc_params::FccParams;
use fcc_rtl::vivado::{Board, BOARDS};
use fcc_rtl::{generate, vivado, Generated, Layout};
use rand::{Rng, SeedableRng};

fn stubs() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/xilinx_stub")
}

/// Whether `gcc` runs. Missing, it skips a test, except in CI (`CI=true`),
/// where it fails the test.
fn gcc_present() -> bool {
    let ok = Command::new("gcc")
        .arg("--version")
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .status()
        .is_ok();
    if !ok && std::env::var("CI").is_ok_and(|v| v == "true") {
        panic!("gcc is not installed and CI=true: install it (Debian: apt-get install gcc)");
    }
    ok
}

/// A configuration every board can run (16 x 256 at 100 MHz).
fn small() -> FccParams {
    FccParams {
        rows: 16,
        cols: 256,
        clock_mhz: 100.0,
        ..Default::default()
    }
}

/// The column core's build of the same size (K = 3, its smallest).
fn small_column() -> FccParams {
    FccParams {
        fsize: 3,
        scan: fcc_params::Scan::Column,
        ..small()
    }
}

/// The example and `fcc_regs.h` of `board` for the generated `g`, written
/// to a fresh directory.
fn written(board: Board, g: &Generated) -> (PathBuf, PathBuf) {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join(format!(
        "fcc-c-example-{}-{}-{}",
        std::process::id(),
        board.info().name,
        g.params.scan.as_str()
    ));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    for (name, text) in vivado::extra_scripts(g, &Layout::default(), board).unwrap() {
        std::fs::write(dir.join(name), text).unwrap();
    }
    let example = dir.join(board.info().example);
    assert!(example.is_file(), "{example:?}");
    assert!(dir.join("fcc_regs.h").is_file());
    (dir, example)
}

fn gcc(args: &[&std::ffi::OsStr]) -> std::process::Output {
    Command::new("gcc").args(args).output().unwrap()
}

/// A host program of the ZC706 example of `g` with `main_c` of the stubs
/// (which includes the example, its own main renamed), linked with the
/// stand-ins of the BSP calls.
fn host_program(g: &Generated, main_c: &str) -> PathBuf {
    let (dir, example) = written(Board::Zc706, g);
    let exe = dir.join(main_c.trim_end_matches(".c"));
    let inc = stubs();
    let define = format!("-DFCC_EXAMPLE=\"{}\"", example.display());
    let out = gcc(&[
        "-std=c99".as_ref(),
        "-Wall".as_ref(),
        "-Wextra".as_ref(),
        "-Werror".as_ref(),
        define.as_ref(),
        "-I".as_ref(),
        inc.as_os_str(),
        "-I".as_ref(),
        dir.as_os_str(),
        inc.join(main_c).as_os_str(),
        inc.join("stub.c").as_os_str(),
        "-o".as_ref(),
        exe.as_os_str(),
    ]);
    assert!(
        out.status.success(),
        "gcc failed:\n{}",
        String::from_utf8_lossy(&out.stderr)
    );
    exe
}

/// Run `exe` with `input` on stdin (fed from another thread: the output
/// pipe fills while input remains); its stdout.
fn run_fed(exe: &Path, input: String) -> String {
    let mut child = Command::new(exe)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .spawn()
        .unwrap();
    let mut stdin = child.stdin.take().unwrap();
    let feeder = std::thread::spawn(move || stdin.write_all(input.as_bytes()));
    let out = child.wait_with_output().unwrap();
    feeder.join().unwrap().unwrap();
    assert!(out.status.success(), "{}", exe.display());
    String::from_utf8(out.stdout).unwrap()
}

#[test]
fn example_compiles_as_c99_with_wall_werror_for_every_board() {
    if !gcc_present() {
        eprintln!("gcc not installed: C example check skipped");
        return;
    }
    let builds = [
        generate(&small()).unwrap(),
        generate(&small_column()).unwrap(),
    ];
    for (board, g) in BOARDS
        .into_iter()
        .flat_map(|b| builds.iter().map(move |g| (b, g)))
    {
        let (dir, example) = written(board, g);
        let obj = dir.join("example.o");
        let inc = stubs();
        let out = gcc(&[
            "-std=c99".as_ref(),
            "-Wall".as_ref(),
            "-Wextra".as_ref(),
            "-Werror".as_ref(),
            "-I".as_ref(),
            inc.as_os_str(),
            "-I".as_ref(),
            dir.as_os_str(),
            "-c".as_ref(),
            example.as_os_str(),
            "-o".as_ref(),
            obj.as_os_str(),
        ]);
        assert!(
            out.status.success(),
            "{} ({} core): gcc failed:\n{}",
            board.info().name,
            g.params.scan.as_str(),
            String::from_utf8_lossy(&out.stderr)
        );
    }
}

#[test]
fn example_retypes_no_register_offset_or_frame_size() {
    let p = small();
    for board in BOARDS {
        let text = fcc_rtl::example::c_example(&p, board);
        // Offsets, masks and sizes come from fcc_regs.h by name.
        for name in [
            "FCC_REG_ID",
            "FCC_REG_HASH_LO",
            "FCC_REG_HASH_HI",
            "FCC_PARAMS_HASH",
            "FCC_REG_CONTROL",
            "FCC_CONTROL_CLEAR_MASK",
            "FCC_CONTROL_IRQ_ENABLE_MASK",
            "FCC_REG_STATUS",
            "FCC_STATUS_FRAME_DONE_MASK",
            "FCC_REG_ROWS_MAX_RESET",
            "FCC_REG_COLS_MAX_RESET",
            "FCC_REG_LABELS_PER_BEAT_RESET",
        ] {
            assert!(text.contains(name), "{}: {name}", board.info().name);
        }
        assert!(!text.contains("0x040"), "no retyped register offset");
        assert!(text.contains("#include \"fcc_regs.h\""));
        // S2MM is armed before MM2S starts.
        let s2mm = text
            .find("fcc_out, FCC_OUT_BYTES, XAXIDMA_DEVICE_TO_DMA")
            .unwrap();
        let mm2s = text
            .find("fcc_in, FCC_IN_BYTES, XAXIDMA_DMA_TO_DEVICE")
            .unwrap();
        assert!(s2mm < mm2s);
        assert!(text.contains(&format!("// Board: {}", board.info().name)));
    }
}

/// The golden model's input word for one pixel (its quantisation, packed as
/// the drivers pack it).
fn golden_word(x: f64, y: f64, z: f64) -> u64 {
    fcc_pixel::pixel_beat(fcc_pixel::quantize_point(x, y, z))
}

#[test]
fn c_quantisation_matches_the_golden_model_on_corners_and_seeded_random_points() {
    if !gcc_present() {
        eprintln!("gcc not installed: C quantisation check skipped");
        return;
    }
    let exe = host_program(&generate(&small()).unwrap(), "pack_main.c");

    // Directed corners: zero of both signs, the rounding halves, the ends of
    // the Q7.8 range and just past them, not-finite values, huge values.
    let corners = [
        0.0,
        -0.0,
        0.5 / 256.0,
        -0.5 / 256.0,
        1.5 / 256.0,
        -1.5 / 256.0,
        0.49 / 256.0,
        32767.0 / 256.0,
        32767.49 / 256.0,
        32767.5 / 256.0,
        -32768.0 / 256.0,
        -32768.49 / 256.0,
        -32768.5 / 256.0,
        f64::NAN,
        f64::INFINITY,
        f64::NEG_INFINITY,
        1e300,
        -1e300,
        f64::MIN_POSITIVE,
        f64::from(f32::MAX),
    ];
    let mut points: Vec<[f64; 3]> = vec![];
    for &c in &corners {
        points.push([c, 1.0, -1.0]);
        points.push([1.0, c, -1.0]);
        points.push([1.0, -1.0, c]);
    }
    let seed = 0x11f_u64;
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(seed);
    for _ in 0..20_000 {
        let mut p = [0.0; 3];
        for v in &mut p {
            *v = match rng.gen_range(0..4) {
                // Within the range, and as f32 (the captures' type).
                0 => rng.gen_range(-128.0..128.0),
                1 => f64::from(rng.gen_range(-130.0f32..130.0)),
                // Exactly on a rounding half.
                2 => (f64::from(rng.gen_range(-65536i32..65536)) + 0.5) / 256.0,
                _ => rng.gen_range(-1e6..1e6),
            };
        }
        points.push(p);
    }
    let input: String = points
        .iter()
        .map(|p| {
            format!(
                "{:x} {:x} {:x}\n",
                p[0].to_bits(),
                p[1].to_bits(),
                p[2].to_bits()
            )
        })
        .collect();
    let got: Vec<u64> = run_fed(&exe, input)
        .lines()
        .map(|l| u64::from_str_radix(l, 16).unwrap())
        .collect();
    assert_eq!(got.len(), points.len());
    for (i, (p, g)) in points.iter().zip(&got).enumerate() {
        let want = golden_word(p[0], p[1], p[2]);
        assert_eq!(
            *g, want,
            "point {i} ({:?}): expected {want:016x}, got {g:016x}, seed {seed:#x}",
            p
        );
    }
}

/// A record's fields by their names in spec §9.4, read from the record's
/// own fields (not from the layout the header is made of).
fn record_fields(r: &fcc_pixel::record::HwRecord) -> Vec<(&'static str, i128)> {
    let mut v: Vec<(&'static str, i128)> = vec![
        ("id", r.id.into()),
        ("points", r.points.into()),
        ("first_row", r.first_row.into()),
        ("last_row", r.last_row.into()),
        ("seam", u8::from(r.seam).into()),
        ("first_col", r.first_col.into()),
        ("last_col", r.last_col.into()),
        ("closed_col", r.closed_col.into()),
        ("range2_min", r.range2_min.into()),
        ("range2_max", r.range2_max.into()),
        ("sum_xx", r.sum_xx.into()),
        ("sum_xy", r.sum_xy.into()),
        ("sum_yy", r.sum_yy.into()),
    ];
    for (i, a) in ["x", "y", "z"].iter().enumerate() {
        v.push((leak(format!("min_{a}")), r.min[i].into()));
        v.push((leak(format!("max_{a}")), r.max[i].into()));
        v.push((leak(format!("sum_{a}")), r.sum[i].into()));
    }
    v
}

fn leak(s: String) -> &'static str {
    Box::leak(s.into_boxed_str())
}

/// `fcc_regs.h` of a column build gives the record layout: a C program
/// that reads seeded random records (packed by `fcc_pixel`, as the core
/// sends them) and the end beat with nothing but the header's macros gets
/// every field back.
#[test]
fn a_column_builds_register_header_decodes_records_in_c() {
    if !gcc_present() {
        eprintln!("gcc not installed: C record layout check skipped");
        return;
    }
    use fcc_pixel::record::{FrameEnd, HwRecord};
    let p = FccParams {
        rows: 24,
        cols: 256,
        fsize: 3,
        scan: fcc_params::Scan::Column,
        ..Default::default()
    };
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR"))
        .join(format!("fcc-c-records-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::write(dir.join("fcc_regs.h"), fcc_rtl::regmap::c_header(&p)).unwrap();
    let names: Vec<&str> = record_fields(&HwRecord::default())
        .iter()
        .map(|f| f.0)
        .collect();
    let mut c = String::from(
        "#include <inttypes.h>\n#include <stdint.h>\n#include <stdio.h>\n#include \"fcc_regs.h\"\n\
         static int64_t field(const uint64_t *w, unsigned word, unsigned shift, unsigned bits, int sign) {\n\
         \x20   uint64_t m = bits >= 64 ? ~UINT64_C(0) : (UINT64_C(1) << bits) - 1;\n\
         \x20   uint64_t v = (w[word] >> shift) & m;\n\
         \x20   if (sign && ((v >> (bits - 1)) & 1)) return (int64_t)(v | ~m);\n\
         \x20   return (int64_t)v;\n}\n\
         int main(void) {\n    uint64_t w[FCC_RECORD_WORDS];\n    unsigned n;\n\
         \x20   if (scanf(\"%u\", &n) != 1) return 1;\n\
         \x20   for (unsigned r = 0; r < n; r++) {\n        for (unsigned i = 0; i < FCC_RECORD_WORDS; i++)\n\
         \x20           if (scanf(\"%\" SCNx64, &w[i]) != 1) return 1;\n",
    );
    for n in &names {
        let u = n.to_uppercase();
        c.push_str(&format!(
            "        printf(\"{n} %\" PRId64 \"\\n\", field(w, FCC_REC_{u}_WORD, FCC_REC_{u}_SHIFT, FCC_REC_{u}_BITS, FCC_REC_{u}_SIGNED));\n"
        ));
    }
    c.push_str(
        "    }\n    if (scanf(\"%\" SCNx64, &w[0]) != 1) return 1;\n\
         \x20   printf(\"records %\" PRId64 \" overflow %\" PRId64 \" frame_error %\" PRId64 \" id %\" PRId64 \"\\n\",\n\
         \x20       field(w, 0, FCC_END_RECORDS_SHIFT, FCC_END_RECORDS_BITS, 0),\n\
         \x20       field(w, 0, FCC_END_OVERFLOW_SHIFT, FCC_END_OVERFLOW_BITS, 0),\n\
         \x20       field(w, 0, FCC_END_FRAME_ERROR_SHIFT, FCC_END_FRAME_ERROR_BITS, 0),\n\
         \x20       field(w, 0, FCC_END_ID_SHIFT, FCC_END_ID_BITS, 0));\n    return 0;\n}\n",
    );
    let src = dir.join("records.c");
    std::fs::write(&src, c).unwrap();
    let exe = dir.join("records");
    let out = gcc(&[
        "-std=c99".as_ref(),
        "-Wall".as_ref(),
        "-Wextra".as_ref(),
        "-Werror".as_ref(),
        "-I".as_ref(),
        dir.as_os_str(),
        src.as_os_str(),
        "-o".as_ref(),
        exe.as_os_str(),
    ]);
    assert!(
        out.status.success(),
        "gcc failed:\n{}",
        String::from_utf8_lossy(&out.stderr)
    );
    // Seeded random records over each field's whole range, and the extremes.
    let seed = 29;
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(seed);
    let mut records = vec![];
    for i in 0..200u32 {
        let ext = i % 2 == 0;
        let u = |rng: &mut rand_chacha::ChaCha8Rng, bits: u32| -> u64 {
            if ext {
                (1u64 << bits) - 1
            } else {
                rng.gen_range(0..1u64 << bits)
            }
        };
        let s = |rng: &mut rand_chacha::ChaCha8Rng, bits: u32| -> i64 {
            let half = 1i64 << (bits - 1);
            if ext {
                -half
            } else {
                rng.gen_range(-half..half)
            }
        };
        let r = HwRecord {
            id: u(&mut rng, 20) as u32,
            points: u(&mut rng, 20) as u32,
            first_row: u(&mut rng, 7) as u32,
            last_row: u(&mut rng, 7) as u32,
            seam: ext || rng.gen(),
            first_col: u(&mut rng, 13) as u32,
            last_col: u(&mut rng, 13) as u32,
            closed_col: u(&mut rng, 13) as u32,
            min: [0; 3].map(|_| s(&mut rng, 16) as i16),
            max: [0; 3].map(|_| s(&mut rng, 16) as i16),
            range2_min: u(&mut rng, 32),
            range2_max: u(&mut rng, 32),
            sum: [0; 3].map(|_| s(&mut rng, 35)),
            sum_xx: u(&mut rng, 50) as i64,
            sum_xy: s(&mut rng, 51),
            sum_yy: u(&mut rng, 50) as i64,
        };
        records.push(r);
    }
    let end = FrameEnd {
        records: 0xF_FFFF,
        overflow: true,
        frame_error: true,
    };
    let mut input = format!("{}\n", records.len());
    let mut want = String::new();
    for r in &records {
        let words = r.pack().unwrap_or_else(|e| panic!("{r:?}: {e}"));
        for w in words {
            input.push_str(&format!("{w:x}\n"));
        }
        for (n, v) in record_fields(r) {
            want.push_str(&format!("{n} {v}\n"));
        }
    }
    input.push_str(&format!("{:x}\n", end.pack().unwrap()));
    want.push_str("records 1048575 overflow 1 frame_error 1 id 0\n");
    let got = run_fed(&exe, input);
    let mismatch = got
        .lines()
        .zip(want.lines())
        .enumerate()
        .find(|(_, (g, w))| g != w);
    if let Some((i, (g, w))) = mismatch {
        panic!("line {i} (seed {seed}): expected {w:?} != got {g:?}");
    }
    assert_eq!(got.lines().count(), want.lines().count(), "seed {seed}");
    let _ = std::fs::remove_dir_all(&dir);
}

/// The column build's example takes its registers, stream limits and record
/// layout from `fcc_regs.h` by name, sends the frame in column order and
/// arms S2MM before MM2S.
#[test]
fn column_example_retypes_no_register_offset_or_record_layout() {
    let p = small_column();
    for board in BOARDS {
        let text = fcc_rtl::example::c_example(&p, board);
        for name in [
            "FCC_REG_RUN_BRIDGE_RESET",
            "FCC_REG_RUN_RING_REACH_RESET",
            "FCC_REG_RUN_OPEN_LIMIT_RESET",
            "FCC_ERROR_OPEN_LIMIT_MASK",
            "FCC_RECORD_WORDS",
            "FCC_REC_##F##_WORD",
            "FCC_END_##F##_SHIFT",
            "XAXIDMA_RX_OFFSET + XAXIDMA_BUFFLEN_OFFSET",
            "c * FCC_ROWS + r",
        ] {
            assert!(text.contains(name), "{}: {name}", board.info().name);
        }
        assert!(!text.contains("#error"));
        assert!(!text.contains("fcc_label("), "no label read-out");
        let beats = fcc_pixel::record::frame_beats_max(p.pixels());
        assert!(text.contains(&format!("#define FCC_OUT_WORDS {beats}u")));
        let s2mm = text
            .find("fcc_out, FCC_OUT_BYTES, XAXIDMA_DEVICE_TO_DMA")
            .unwrap();
        let mm2s = text
            .find("fcc_in, FCC_IN_BYTES, XAXIDMA_DMA_TO_DEVICE")
            .unwrap();
        assert!(s2mm < mm2s);
    }
}

/// The line the column example prints for record `r` (its format, from
/// the record's own fields; `\r\n` ends it, `lines()` takes both off).
fn record_line(r: &fcc_pixel::record::HwRecord) -> String {
    format!(
        "fcc: cluster {}: {} points, columns {}..{}, closed at {}, rows {}..{}, x {}..{}, y {}..{}, z {}..{}",
        r.id,
        r.points,
        r.first_col,
        r.last_col,
        r.closed_col,
        r.first_row,
        r.last_row,
        r.min[0],
        r.max[0],
        r.min[1],
        r.max[1],
        r.min[2],
        r.max[2]
    )
}

/// The column example's `fcc_read_records`, compiled on the host, reads a
/// frame's records as the core sends them (seeded random records over each
/// field's range, packed by `fcc_pixel`) and the end beat, and refuses
/// words that are not one frame's: a cut record, an end beat that counts
/// otherwise.
#[test]
fn column_example_reads_the_records_and_the_end_beat_of_a_frame() {
    if !gcc_present() {
        eprintln!("gcc not installed: C record reading check skipped");
        return;
    }
    use fcc_pixel::record::{FrameEnd, HwRecord};
    let exe = host_program(&generate(&small_column()).unwrap(), "records_main.c");
    let run = |words: &[u64]| -> String {
        let input: String = std::iter::once(format!("{}\n", words.len()))
            .chain(words.iter().map(|w| format!("{w:x}\n")))
            .collect();
        run_fed(&exe, input)
    };
    let seed = 31;
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(seed);
    let s16 = |rng: &mut rand_chacha::ChaCha8Rng| rng.gen_range(i16::MIN..=i16::MAX);
    let records: Vec<HwRecord> = (0..40)
        .map(|i| {
            let ext = i % 5 == 0;
            HwRecord {
                id: if ext {
                    (1 << 20) - 1
                } else {
                    rng.gen_range(0..1 << 20)
                },
                points: rng.gen_range(1..1 << 20),
                first_row: rng.gen_range(0..128),
                last_row: rng.gen_range(0..128),
                seam: rng.gen(),
                first_col: rng.gen_range(0..1 << 13),
                last_col: rng.gen_range(0..1 << 13),
                closed_col: if ext {
                    (1 << 13) - 1
                } else {
                    rng.gen_range(0..1 << 13)
                },
                min: [0; 3].map(|_| if ext { i16::MIN } else { s16(&mut rng) }),
                max: [0; 3].map(|_| if ext { i16::MAX } else { s16(&mut rng) }),
                range2_min: rng.gen_range(0..1 << 32),
                range2_max: rng.gen_range(0..1 << 32),
                sum: [0; 3].map(|_| rng.gen_range(-(1i64 << 34)..1i64 << 34)),
                sum_xx: rng.gen_range(0..1i64 << 50),
                sum_xy: rng.gen_range(-(1i64 << 50)..1i64 << 50),
                sum_yy: rng.gen_range(0..1i64 << 50),
            }
        })
        .collect();
    let frame = |n: usize, counted: u32, overflow: bool| -> Vec<u64> {
        let mut w: Vec<u64> = records[..n]
            .iter()
            .flat_map(|r| r.pack().unwrap_or_else(|e| panic!("{r:?}: {e}")))
            .collect();
        let end = FrameEnd {
            records: counted,
            overflow,
            frame_error: false,
        };
        w.push(end.pack().unwrap());
        w
    };
    for (n, overflow) in [(40usize, false), (1, true), (0, false)] {
        let got = run(&frame(n, n as u32, overflow));
        let mut want: Vec<String> = records[..n].iter().map(record_line).collect();
        want.push(format!(
            "fcc: end of frame: {n} records, overflow {}, frame error 0",
            u8::from(overflow)
        ));
        want.push(format!("returned {n}"));
        let got: Vec<&str> = got.lines().collect();
        if let Some((i, (g, w))) = got.iter().zip(&want).enumerate().find(|(_, (g, w))| g != w) {
            panic!("{n} records, line {i} (seed {seed}): expected {w:?} != got {g:?}");
        }
        assert_eq!(got.len(), want.len(), "{n} records (seed {seed})");
    }
    // Not one frame's: a record cut short, an end beat counting otherwise.
    let mut cut = frame(3, 3, false);
    cut.remove(5);
    let got = run(&cut);
    assert!(
        got.contains("33 beats: not records of 11 beats and an end beat"),
        "{got}"
    );
    assert!(got.ends_with("returned -1\n"), "{got}");
    let got = run(&frame(3, 4, false));
    assert!(
        got.contains("the end beat counts 4 records, 3 came"),
        "{got}"
    );
    assert!(got.ends_with("returned -1\n"), "{got}");
    assert!(run(&[]).ends_with("returned -1\n"));
}
