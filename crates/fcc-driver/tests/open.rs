//! `Driver::open` on a register-level fake of the core and the DMA: the
//! checks that need no simulation (ID word, hash, labels per beat, DMA
//! length width, a DMA reset that never ends, the run registers and the
//! ERROR register, the column core's stream limits). Frames are run on the
//! virtual board (`fcc-sim`).

use std::collections::HashMap;
use std::fmt;

use fcc_driver::{
    dma, BuildExpect, DmaBuffer, Driver, Error, Hal, Pixels, RefusedBits, RunConfig, StreamLimits,
    Window,
};
use fcc_regmap::{bits, offset, ID_MAGIC};

#[derive(Debug)]
struct Never;
impl fmt::Display for Never {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("never")
    }
}

struct Buf(Vec<u8>, u64);
impl DmaBuffer for Buf {
    fn phys(&self) -> u64 {
        self.1
    }
    fn bytes(&self) -> &[u8] {
        &self.0
    }
    fn bytes_mut(&mut self) -> &mut [u8] {
        &mut self.0
    }
}

/// Registers as a map; time moves 1 us per access; the DMA's reset ends
/// at once unless `reset_sticks`. The run registers take a value within
/// the build's limits (docs/rtl.md) and otherwise keep theirs and set their
/// ERROR bit; ERROR is write-1-to-clear. `writes` logs every core write.
struct Fake {
    core: HashMap<u32, u32>,
    dma: HashMap<u32, u32>,
    t: u64,
    reset_sticks: bool,
    writes: Vec<(u32, u32)>,
    /// Physical address of every buffer.
    phys: u64,
}

/// The run registers' rule of docs/rtl.md for the fake's build (K_MAX 7,
/// ROWS_MAX 16, COLS_MAX 256): (register, ERROR bit, accepts).
type Accepts = fn(u32) -> bool;

fn run_rule(o: u32) -> Option<(u32, Accepts)> {
    Some(match o {
        offset::RUN_K => (bits::ERROR_K, |v| v % 2 == 1 && (3..=7).contains(&v)),
        offset::RUN_TH_H => (bits::ERROR_TH_H, |v| (1..=0x8000).contains(&v)),
        offset::RUN_TH_V => (bits::ERROR_TH_V, |v| (1..=0x8000).contains(&v)),
        offset::RUN_ROWS => (bits::ERROR_ROWS, |v| (1..=16).contains(&v)),
        offset::RUN_COLS => (bits::ERROR_COLS, |v| (32..=256).contains(&v)),
        offset::RUN_SLOPE_H => (bits::ERROR_SLOPE_H, |v| v <= 0xffff),
        offset::RUN_SLOPE_V => (bits::ERROR_SLOPE_V, |v| v <= 0xffff),
        offset::RUN_BRIDGE => (bits::ERROR_BRIDGE, |v| v <= 0xfff),
        offset::RUN_RING_REACH => (bits::ERROR_RING_REACH, |v| v <= 0xfff),
        offset::RUN_OPEN_LIMIT => (bits::ERROR_OPEN_LIMIT, |v| (1..=511).contains(&v)),
        _ => return None,
    })
}

const HASH: u64 = 0x0123_4567_89ab_cdef;

fn fake(lpb: u32) -> Fake {
    let core = HashMap::from([
        (offset::ID, ID_MAGIC),
        (offset::HASH_LO, HASH as u32),
        (offset::HASH_HI, (HASH >> 32) as u32),
        (offset::K_MAX, 7),
        (offset::ROWS_MAX, 16),
        (offset::COLS_MAX, 256),
        (offset::LABEL_BITS, 11),
        (offset::LABELS_PER_BEAT, lpb),
        (offset::CLOCK_KHZ, 200_000),
        (offset::STATUS, bits::STATUS_IDLE),
        (offset::RUN_K, 7),
        (offset::RUN_TH_H, 128),
        (offset::RUN_TH_V, 256),
        (offset::RUN_ROWS, 16),
        (offset::RUN_COLS, 256),
        (offset::RUN_SLOPE_H, 0),
        (offset::RUN_SLOPE_V, 3277),
    ]);
    Fake {
        core,
        dma: HashMap::from([
            (dma::MM2S_DMASR, dma::SR_HALTED),
            (dma::S2MM_DMASR, dma::SR_HALTED),
        ]),
        t: 0,
        reset_sticks: false,
        writes: Vec::new(),
        phys: 0x1000_0000,
    }
}

impl Hal for Fake {
    type Buffer = Buf;
    type Error = Never;
    fn read32(&mut self, w: Window, o: u32) -> Result<u32, Never> {
        self.t += 1000;
        let m = match w {
            Window::Core => &self.core,
            Window::Dma => &self.dma,
        };
        Ok(m.get(&o).copied().unwrap_or(0))
    }
    fn write32(&mut self, w: Window, o: u32, v: u32) -> Result<(), Never> {
        self.t += 1000;
        match w {
            Window::Core => {
                self.writes.push((o, v));
                if o == offset::CONTROL {
                    self.core.insert(o, v & bits::CONTROL_IRQ_ENABLE);
                } else if o == offset::ERROR {
                    *self.core.entry(o).or_default() &= !v;
                } else if let Some((bit, ok)) = run_rule(o) {
                    if ok(v) {
                        self.core.insert(o, v);
                    } else {
                        *self.core.entry(offset::ERROR).or_default() |= bit;
                    }
                }
            }
            Window::Dma => {
                let v = if o == dma::MM2S_DMACR && !self.reset_sticks {
                    v & !dma::CR_RESET
                } else {
                    v
                };
                self.dma.insert(o, v);
            }
        }
        Ok(())
    }
    fn alloc_dma(&mut self, len: usize) -> Result<Buf, Never> {
        Ok(Buf(vec![0; len], self.phys))
    }
    fn cache_clean(&mut self, _: &mut Buf, _: usize, _: usize) -> Result<(), Never> {
        Ok(())
    }
    fn cache_invalidate(&mut self, _: &mut Buf, _: usize, _: usize) -> Result<(), Never> {
        Ok(())
    }
    fn wait_irq(&mut self, us: u64) -> Result<bool, Never> {
        self.t += us * 1000;
        Ok(false)
    }
    fn now_ns(&mut self) -> u64 {
        self.t
    }
}

fn expect() -> BuildExpect {
    BuildExpect {
        hash: HASH,
        dma_length_bits: 16,
        dma_addr_bits: 32,
        column: false,
    }
}

fn open_err(hal: Fake, e: &BuildExpect) -> Error<Never> {
    match Driver::open(hal, e) {
        Ok(_) => panic!("open should fail"),
        Err(e) => e,
    }
}

#[test]
fn wrong_id_word_says_no_fcc_core() {
    let mut f = fake(4);
    f.core.insert(offset::ID, 0xdead_beef);
    let e = open_err(f, &expect());
    assert!(matches!(e, Error::NotFcc { id: 0xdead_beef }), "{e}");
    assert!(e.to_string().contains("no FCC core"), "{e}");
}

#[test]
fn other_hash_names_both_hashes() {
    let e = open_err(
        fake(4),
        &BuildExpect {
            hash: 1,
            ..expect()
        },
    );
    let msg = e.to_string();
    assert!(
        msg.contains("0123456789abcdef") && msg.contains("0000000000000001"),
        "{msg}"
    );
}

#[test]
fn two_labels_per_beat_is_refused_for_the_dma() {
    let e = open_err(fake(2), &expect());
    assert!(e.to_string().contains("--labels-per-beat 4"), "{e}");
}

#[test]
fn dma_length_width_outside_pg021_range_is_refused() {
    let e = open_err(
        fake(4),
        &BuildExpect {
            dma_length_bits: 27,
            ..expect()
        },
    );
    assert!(e.to_string().contains("c_sg_length_width"), "{e}");
}

#[test]
fn dma_reset_that_never_ends_is_a_clear_error() {
    let mut f = fake(4);
    f.reset_sticks = true;
    let e = open_err(f, &expect());
    assert!(matches!(e, Error::ResetStuck { .. }), "{e}");
}

#[test]
fn build_whose_largest_frame_exceeds_the_dma_length_register_is_refused_at_open() {
    // The build's 16 x 256 frame: 16 x 256 x 8 bytes = 32 KiB > 2^12 - 1.
    let e = open_err(
        fake(4),
        &BuildExpect {
            dma_length_bits: 12,
            ..expect()
        },
    );
    assert!(
        matches!(
            e,
            Error::TooLong {
                bytes: 32768,
                length_bits: 12,
                ..
            }
        ),
        "{e}"
    );
    assert!(e.to_string().contains("c_sg_length_width"), "{e}");
    // 2^15 - 1 < 32768 <= 2^16 - 1: one bit short is refused, the exact width opens.
    for (bits, ok) in [(15, false), (16, true)] {
        let r = Driver::open(
            fake(4),
            &BuildExpect {
                dma_length_bits: bits,
                ..expect()
            },
        );
        assert_eq!(r.is_ok(), ok, "{bits} bits");
    }
}

#[test]
fn defaults_are_read_from_the_run_registers() {
    let mut f = fake(4);
    f.core.insert(offset::RUN_K, 5);
    f.core.insert(offset::RUN_COLS, 64);
    let d = Driver::open(f, &expect()).unwrap();
    assert_eq!(
        d.defaults(),
        RunConfig {
            rows: 16,
            cols: 64,
            k: 5,
            th_h_q: 128,
            th_v_q: 256,
            th_h_slope_q: 0,
            th_v_slope_q: 3277,
            limits: None,
        }
    );
}

#[test]
fn run_values_are_written_to_the_run_registers() {
    let mut d = Driver::open(fake(4), &expect()).unwrap();
    let run = RunConfig {
        rows: 3,
        cols: 32,
        k: 3,
        th_h_q: 1,
        th_v_q: 0x8000,
        th_h_slope_q: 0xffff,
        th_v_slope_q: 1,
        limits: None,
    };
    d.program_run(&run).unwrap();
    let c = &d.hal().core;
    let got = [
        offset::RUN_ROWS,
        offset::RUN_COLS,
        offset::RUN_K,
        offset::RUN_TH_H,
        offset::RUN_TH_V,
        offset::RUN_SLOPE_H,
        offset::RUN_SLOPE_V,
    ]
    .map(|o| c[&o]);
    assert_eq!(got, [3, 32, 3, 1, 0x8000, 0xffff, 1]);
    assert_eq!(c.get(&offset::ERROR).copied().unwrap_or(0), 0);
}

#[test]
fn refused_run_values_name_their_registers_and_clear_error() {
    let mut d = Driver::open(fake(4), &expect()).unwrap();
    let base = d.defaults();
    for (run, want, names) in [
        (
            RunConfig { k: 9, ..base },
            bits::ERROR_K,
            &["RUN_K = 9"][..],
        ),
        (RunConfig { k: 4, ..base }, bits::ERROR_K, &["RUN_K = 4"]),
        (RunConfig { k: 1, ..base }, bits::ERROR_K, &["RUN_K = 1"]),
        (
            RunConfig { th_h_q: 0, ..base },
            bits::ERROR_TH_H,
            &["RUN_TH_H = 0"],
        ),
        (
            RunConfig {
                th_v_q: 0x8001,
                ..base
            },
            bits::ERROR_TH_V,
            &["RUN_TH_V = 32769"],
        ),
        (
            RunConfig { rows: 0, ..base },
            bits::ERROR_ROWS,
            &["RUN_ROWS = 0"],
        ),
        (
            RunConfig { rows: 17, ..base },
            bits::ERROR_ROWS,
            &["RUN_ROWS = 17"],
        ),
        (
            RunConfig { cols: 257, ..base },
            bits::ERROR_COLS,
            &["RUN_COLS = 257"],
        ),
        (
            RunConfig { cols: 31, ..base },
            bits::ERROR_COLS,
            &["RUN_COLS = 31"],
        ),
        (
            RunConfig {
                th_v_slope_q: 0x1_0000,
                ..base
            },
            bits::ERROR_SLOPE_V,
            &["RUN_SLOPE_V = 65536"],
        ),
        (
            RunConfig {
                k: 13,
                cols: 300,
                ..base
            },
            bits::ERROR_K | bits::ERROR_COLS,
            &["RUN_K = 13", "RUN_COLS = 300"],
        ),
    ] {
        // A stale bit from before must not be blamed on this run.
        d.hal().core.insert(offset::ERROR, bits::ERROR_ROWS);
        d.hal().writes.clear();
        let e = d
            .program_run(&run)
            .expect_err(&format!("{run:?} should be refused"));
        match &e {
            Error::RunRefused {
                bits: b, run: r, ..
            } => {
                assert_eq!(*b, RefusedBits(want), "{run:?}: {e}");
                assert_eq!(r, &run);
            }
            _ => panic!("{run:?}: expected a refusal, got {e}"),
        }
        let msg = e.to_string();
        for n in names {
            assert!(msg.contains(n), "{run:?}: {msg}");
        }
        assert!(msg.contains("K_MAX 7, ROWS_MAX 16, COLS_MAX 256"), "{msg}");
        // ERROR cleared first (all bits), and the refused bits written back.
        let w = &d.hal().writes;
        assert_eq!(w.first(), Some(&(offset::ERROR, 0x7f)), "{w:?}");
        assert_eq!(w.last(), Some(&(offset::ERROR, want)), "{w:?}");
        assert_eq!(d.hal().core[&offset::ERROR], 0, "{run:?}");
        // The core kept its values; a good run goes through.
        assert_eq!(d.hal().core[&offset::RUN_K], 7);
    }
    d.program_run(&base).unwrap();
}

#[test]
fn a_frame_that_never_finishes_times_out_with_the_state_seen() {
    let mut d = Driver::open(fake(4), &expect()).unwrap();
    let run = d.defaults();
    let mut labels = vec![0; 4096];
    let xyz = vec![1.0f32; 4096 * 3];
    let e = d
        .run_frame(&run, Pixels::XyzF32(&xyz), &mut labels)
        .unwrap_err();
    match &e {
        Error::Timeout { stage, .. } => assert!(stage.contains("frame-done"), "{e}"),
        _ => panic!("expected a timeout, got {e}"),
    }
    // MM2S was started with the whole frame before the wait.
    let tx = d.hal().dma.get(&dma::MM2S_LENGTH).copied();
    assert_eq!(tx, Some(4096 * 8));
}

#[test]
fn buffer_above_4_gib_is_refused_by_a_32_bit_dma_and_taken_by_a_40_bit_one() {
    let high = |addr_bits| {
        let mut f = fake(4);
        f.phys = 0x8_0000_0000;
        Driver::open(
            f,
            &BuildExpect {
                dma_addr_bits: addr_bits,
                ..expect()
            },
        )
    };
    let e = match high(32) {
        Ok(_) => panic!("a 32-bit DMA took a buffer at 32 GiB"),
        Err(e) => e,
    };
    assert!(
        matches!(
            e,
            Error::BufferAddress {
                phys: 0x8_0000_0000,
                addr_bits: 32,
                ..
            }
        ),
        "{e}"
    );
    assert!(e.to_string().contains("c_addr_width"), "{e}");
    // 40 bits (the ZCU104): the MSB halves of both addresses are written.
    let mut d = high(40).unwrap();
    let run = d.defaults();
    let mut labels = vec![0; 4096];
    let pts = vec![None; 4096];
    let _ = d.run_frame(&run, Pixels::Points(&pts), &mut labels);
    assert_eq!(d.hal().dma.get(&dma::MM2S_SA_MSB), Some(&0x8));
    assert_eq!(d.hal().dma.get(&dma::S2MM_DA_MSB), Some(&0x8));
    assert_eq!(d.hal().dma.get(&dma::MM2S_SA), Some(&0));
    // The pixel buffer (16 x 256 x 8 bytes, the larger) ending exactly at
    // 2^40 fits; one cache line higher it does not.
    for (phys, ok) in [
        ((1u64 << 40) - 32768, true),
        ((1u64 << 40) - 32768 + 32, false),
    ] {
        let mut f = fake(4);
        f.phys = phys;
        let r = Driver::open(
            f,
            &BuildExpect {
                dma_addr_bits: 40,
                ..expect()
            },
        );
        assert_eq!(r.is_ok(), ok, "buffer at 0x{phys:x}");
    }
}

#[test]
fn a_32_bit_dma_gets_no_msb_address_writes() {
    let mut d = Driver::open(fake(4), &expect()).unwrap();
    let run = d.defaults();
    let mut labels = vec![0; 4096];
    let pts = vec![None; 4096];
    let _ = d.run_frame(&run, Pixels::Points(&pts), &mut labels);
    assert_eq!(d.hal().dma.get(&dma::MM2S_SA), Some(&0x1000_0000));
    assert!(!d.hal().dma.contains_key(&dma::MM2S_SA_MSB));
    assert!(!d.hal().dma.contains_key(&dma::S2MM_DA_MSB));
}

/// A column build: the fake's stream-limit registers hold its limits.
fn column_fake() -> Fake {
    let mut f = fake(4);
    f.core.extend([
        (offset::RUN_BRIDGE, 16),
        (offset::RUN_RING_REACH, 0xfff),
        (offset::RUN_OPEN_LIMIT, 511),
    ]);
    f
}

fn column() -> BuildExpect {
    BuildExpect {
        column: true,
        dma_length_bits: 19,
        ..expect()
    }
}

#[test]
fn a_column_build_reads_writes_and_checks_its_stream_limits() {
    let mut d = Driver::open(column_fake(), &column()).unwrap();
    let base = d.defaults();
    let limits = StreamLimits {
        bridge: 16,
        ring_reach: 0xfff,
        open_limit: 511,
    };
    assert_eq!(base.limits, Some(limits));
    let run = RunConfig {
        limits: Some(StreamLimits {
            bridge: 2,
            ring_reach: 6,
            open_limit: 12,
        }),
        ..base
    };
    d.hal().writes.clear();
    d.program_run(&run).unwrap();
    let c = &d.hal().core;
    let got = [
        offset::RUN_BRIDGE,
        offset::RUN_RING_REACH,
        offset::RUN_OPEN_LIMIT,
    ]
    .map(|o| c[&o]);
    assert_eq!(got, [2, 6, 12]);
    // ERROR is cleared with the stream bits too.
    assert_eq!(d.hal().writes.first(), Some(&(offset::ERROR, 0x3ff)));
    for (l, want, name) in [
        (
            StreamLimits {
                open_limit: 0,
                ..limits
            },
            bits::ERROR_OPEN_LIMIT,
            "RUN_OPEN_LIMIT = 0 (takes 1 ..= 511 clusters)",
        ),
        (
            StreamLimits {
                bridge: 0x1000,
                ..limits
            },
            bits::ERROR_BRIDGE,
            "RUN_BRIDGE = 4096",
        ),
        (
            StreamLimits {
                ring_reach: 5000,
                ..limits
            },
            bits::ERROR_RING_REACH,
            "RUN_RING_REACH = 5000",
        ),
    ] {
        let run = RunConfig {
            limits: Some(l),
            ..base
        };
        let e = d.program_run(&run).expect_err("refused");
        assert!(
            matches!(e, Error::RunRefused { bits, .. } if bits == RefusedBits(want)),
            "{e}"
        );
        assert!(e.to_string().contains(name), "{e}");
    }
    // `None` leaves the registers as they are.
    d.hal().writes.clear();
    d.program_run(&RunConfig {
        limits: None,
        ..base
    })
    .unwrap();
    let w = &d.hal().writes;
    assert!(
        !w.iter().any(|(o, _)| *o == offset::RUN_OPEN_LIMIT),
        "{w:?}"
    );
}

#[test]
fn each_core_refuses_the_others_call_and_the_row_core_stream_limits() {
    let pts = vec![None; 4096];
    let mut d = Driver::open(column_fake(), &column()).unwrap();
    let run = d.defaults();
    let e = d
        .run_frame(&run, Pixels::Points(&pts), &mut vec![0; 4096])
        .unwrap_err();
    assert!(e.to_string().contains("use run_records"), "{e}");

    let mut d = Driver::open(fake(4), &expect()).unwrap();
    let run = d.defaults();
    let mut records = Vec::new();
    let e = d
        .run_records(&run, Pixels::Points(&pts), &mut records)
        .unwrap_err();
    assert!(e.to_string().contains("use run_frame"), "{e}");
    let e = d
        .program_run(&RunConfig {
            limits: Some(StreamLimits {
                bridge: 1,
                ring_reach: 1,
                open_limit: 1,
            }),
            ..run
        })
        .unwrap_err();
    assert!(e.to_string().contains("column core only"), "{e}");
}

#[test]
fn a_column_build_takes_labels_per_beat_as_it_is_and_sizes_s2mm_for_records() {
    // 16 x 256 pixels: (4096 x 11 + 1) x 8 = 360,456 bytes of records
    // need 19 length bits.
    for (bits, ok) in [(18, false), (19, true)] {
        let r = Driver::open(
            column_fake(),
            &BuildExpect {
                dma_length_bits: bits,
                ..column()
            },
        );
        match r {
            Ok(_) => assert!(ok, "{bits} bits took a frame of records"),
            Err(e) => {
                assert!(!ok, "{bits} bits: {e}");
                assert!(matches!(e, Error::TooLong { bytes: 360_456, .. }), "{e}");
            }
        }
    }
    // Labels per beat do not matter for records.
    let mut f = column_fake();
    f.core.insert(offset::LABELS_PER_BEAT, 1);
    assert!(Driver::open(
        f,
        &BuildExpect {
            dma_length_bits: 19,
            ..column()
        }
    )
    .is_ok());
}
