//! The register file `fcc_regs` alone under Verilator: power-on values of
//! every register, unmapped reads, writes with AW and W in either order and
//! random BREADY / RREADY stalls, the frame-end latch, the sticky FRAME_DONE
//! bit and the interrupt, soft reset and clear, and a seeded random sequence
//! checked against a reference model of the map.

use fcc_params::FccParams;
use fcc_rtl::regmap::{self, bits, offset};
use fcc_sim::{load_regs, AxilMaster, RegsDut, RegsIn, WriteOrder};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

fn dut(p: &FccParams) -> RegsDut {
    let model = match load_regs(p) {
        Ok(m) => m,
        Err(e) => panic!("{e}"),
    };
    let mut d = RegsDut::new(model);
    d.reset(2);
    d.idle();
    d
}

fn builds() -> Vec<FccParams> {
    vec![
        FccParams::default(),
        FccParams {
            rows: 128,
            cols: 2048,
            fsize: 11,
            label_bits: 16,
            labels_per_beat: 2,
            clock_mhz: 150.0,
            th_h_slope: 0.01,
            th_v_slope: 0.035,
            ..Default::default()
        },
    ]
}

/// Offsets that no register uses: the gaps of the map and the window's end.
fn unmapped(p: &FccParams) -> Vec<u32> {
    let used: Vec<u32> = regmap::registers(p).iter().map(|r| r.offset).collect();
    (0..(1u32 << regmap::ADDR_BITS))
        .step_by(4)
        .filter(|o| !used.contains(o))
        .filter(|o| o % 0x1c == 0 || *o == 0xffc)
        .collect()
}

#[test]
fn power_on_value_of_every_register_and_unmapped_reads_zero() {
    for p in builds() {
        let mut d = dut(&p);
        let mut m = AxilMaster::new(1);
        for r in regmap::registers(&p) {
            let got = m.read(&mut d, r.offset).unwrap();
            assert_eq!(
                got,
                r.reset,
                "{} ({:#05x}): expected {:#010x} != got {got:#010x} ({})",
                r.name,
                r.offset,
                r.reset,
                fcc_rtl::param_summary(&p)
            );
        }
        for o in unmapped(&p) {
            let (got, resp) = m.read_resp(&mut d, o).unwrap();
            assert_eq!((got, resp), (0, 0), "unmapped {o:#05x}");
            // Writes there are accepted and change nothing.
            m.write_ok(&mut d, o, 0xffff_ffff).unwrap();
        }
        let id = m.read(&mut d, offset::ID).unwrap();
        assert_eq!(id, regmap::ID_MAGIC);
        let lo = m.read(&mut d, offset::HASH_LO).unwrap();
        let hi = m.read(&mut d, offset::HASH_HI).unwrap();
        assert_eq!(format!("{hi:08x}{lo:08x}"), p.hash());
        assert_eq!(m.read(&mut d, offset::K_MAX).unwrap(), p.fsize as u32);
        assert_eq!(m.read(&mut d, offset::COLS_MAX).unwrap(), p.cols as u32);
    }
}

#[test]
fn read_only_registers_ignore_writes() {
    let p = FccParams::default();
    let mut d = dut(&p);
    let mut m = AxilMaster::new(2);
    for r in regmap::registers(&p) {
        if r.access == regmap::Access::ReadOnly {
            m.write_ok(&mut d, r.offset, !r.reset).unwrap();
            assert_eq!(m.read(&mut d, r.offset).unwrap(), r.reset, "{}", r.name);
        }
    }
}

#[test]
fn writes_with_aw_and_w_in_either_order_and_ready_stalls() {
    let p = FccParams::default();
    let mut d = dut(&p);
    for (k, order) in [
        WriteOrder::Together,
        WriteOrder::AwFirst(1),
        WriteOrder::AwFirst(5),
        WriteOrder::WFirst(1),
        WriteOrder::WFirst(5),
    ]
    .into_iter()
    .enumerate()
    {
        for stall in [0.0, 0.5, 0.9] {
            let seed = 100 + k as u64;
            let mut m = AxilMaster::new(seed);
            m.order = order;
            m.stall = stall;
            for v in [bits::CONTROL_IRQ_ENABLE, 0, u32::MAX, 0] {
                m.write_ok(&mut d, offset::CONTROL, v).unwrap();
                let got = m.read(&mut d, offset::CONTROL).unwrap();
                let want = v & bits::CONTROL_IRQ_ENABLE;
                assert_eq!(
                    got, want,
                    "{order:?} stall {stall}: CONTROL expected {want:#x} != got {got:#x} (seed {seed})"
                );
            }
        }
    }
}

/// A frame end as the core gives it: one cycle announcing phase Out
/// (`out_next`), then one with the last beat sent and the given counters.
fn end_frame(d: &mut RegsDut, counters: RegsIn) {
    let out = RegsIn {
        out_next: 1,
        s_axil_bready: 1,
        s_axil_rready: 1,
        ..d.live
    };
    d.step(&out);
    let inp = RegsIn {
        frame_sent: 1,
        s_axil_bready: 1,
        s_axil_rready: 1,
        ..counters
    };
    d.step(&inp);
}

fn counters(rng: &mut ChaCha8Rng) -> RegsIn {
    RegsIn {
        clusters: rng.gen(),
        provisional: rng.gen(),
        unlabelled: rng.gen::<u32>() & 0xf_ffff,
        joins: rng.gen::<u32>() & 0xff_ffff,
        gear_stalls: rng.gen::<u32>() & 0xff_ffff,
        overflow: rng.gen::<u8>() & 1,
        frame_error: rng.gen::<u8>() & 1,
        ..Default::default()
    }
}

#[test]
fn frame_end_latches_status_sets_frame_done_and_irq() {
    let p = FccParams::default();
    let mut d = dut(&p);
    let mut m = AxilMaster::new(3);
    let mut rng = ChaCha8Rng::seed_from_u64(3);
    let c = counters(&mut rng);
    end_frame(&mut d, c);
    // The live counters move on; the latched ones must not.
    d.live = counters(&mut rng);
    let o = d.idle();
    assert_eq!(
        o.frame_done, 1,
        "frame_done pulses the cycle after frame_end"
    );
    assert_eq!(
        (o.st_clusters, o.st_provisional, o.st_unlabelled, o.st_joins),
        (c.clusters, c.provisional, c.unlabelled, c.joins)
    );
    assert_eq!(d.idle().frame_done, 0, "frame_done is one cycle long");
    assert_eq!(o.irq, 0, "irq stays low while disabled");
    let reads = [
        (offset::CLUSTERS, u32::from(c.clusters)),
        (offset::PROVISIONAL, u32::from(c.provisional)),
        (offset::UNLABELLED, c.unlabelled),
        (offset::JOINS, c.joins),
        (offset::GEAR_STALLS, c.gear_stalls),
        (
            offset::FRAME_FLAGS,
            u32::from(c.overflow) | (u32::from(c.frame_error) << 1),
        ),
        (offset::FRAME_COUNT, 1),
        (offset::STATUS, bits::STATUS_FRAME_DONE),
    ];
    for (off, want) in reads {
        let got = m.read(&mut d, off).unwrap();
        assert_eq!(got, want, "{off:#05x}: expected {want:#x} != got {got:#x}");
    }
    // Enabling the interrupt raises irq for the pending frame.
    m.write_ok(&mut d, offset::CONTROL, bits::CONTROL_IRQ_ENABLE)
        .unwrap();
    assert_eq!(d.idle().irq, 1, "irq: FRAME_DONE and enabled");
    // Masking lowers it, unmasking raises it again.
    m.write_ok(&mut d, offset::CONTROL, 0).unwrap();
    assert_eq!(d.idle().irq, 0, "irq masked");
    m.write_ok(&mut d, offset::CONTROL, bits::CONTROL_IRQ_ENABLE)
        .unwrap();
    assert_eq!(d.idle().irq, 1);
    // Writing 0 to STATUS clears nothing; writing 1 clears FRAME_DONE.
    m.write_ok(&mut d, offset::STATUS, 0).unwrap();
    assert_eq!(d.idle().irq, 1, "W1C: a 0 bit leaves FRAME_DONE set");
    m.write_ok(&mut d, offset::STATUS, bits::STATUS_FRAME_DONE)
        .unwrap();
    assert_eq!(d.idle().irq, 0, "W1C cleared FRAME_DONE");
    assert_eq!(m.read(&mut d, offset::STATUS).unwrap(), 0);
    // The core's idle flag shows in STATUS (registered from `idle_next`).
    d.live.idle_next = 1;
    d.idle();
    assert_eq!(
        m.read(&mut d, offset::STATUS).unwrap(),
        bits::STATUS_IDLE,
        "STATUS.IDLE follows the core"
    );
    // A second frame counts and sets the interrupt again.
    end_frame(&mut d, c);
    assert_eq!(d.idle().irq, 1);
    assert_eq!(m.read(&mut d, offset::FRAME_COUNT).unwrap(), 2);
}

#[test]
fn soft_reset_pulses_core_reset_and_keeps_the_registers() {
    let p = FccParams::default();
    let mut d = dut(&p);
    let mut m = AxilMaster::new(4);
    let mut rng = ChaCha8Rng::seed_from_u64(4);
    assert_eq!(d.idle().core_rst, 0, "core_rst ends after rst");
    end_frame(&mut d, counters(&mut rng));
    m.write_ok(
        &mut d,
        offset::CONTROL,
        bits::CONTROL_SOFT_RESET | bits::CONTROL_IRQ_ENABLE,
    )
    .unwrap();
    // The write happened in the cycle after both channels were held; the
    // pipeline reset follows within two cycles and lasts one.
    let mut high = 0;
    for _ in 0..6 {
        high += u32::from(d.idle().core_rst);
    }
    assert_eq!(high, 1, "soft reset: core_rst high for exactly one cycle");
    assert_eq!(
        m.read(&mut d, offset::CONTROL).unwrap(),
        bits::CONTROL_IRQ_ENABLE,
        "SOFT_RESET reads 0, IRQ_ENABLE kept"
    );
    assert_eq!(m.read(&mut d, offset::FRAME_COUNT).unwrap(), 1);
    // Power-on reset: core_rst follows rst, one cycle late.
    d.reset(1);
    assert_eq!(d.idle().core_rst, 1);
    assert_eq!(d.idle().core_rst, 0);
    assert_eq!(m.read(&mut d, offset::CONTROL).unwrap(), 0);
}

#[test]
fn clear_zeroes_count_status_and_frame_done() {
    let p = FccParams::default();
    let mut d = dut(&p);
    let mut m = AxilMaster::new(5);
    let mut rng = ChaCha8Rng::seed_from_u64(5);
    end_frame(&mut d, counters(&mut rng));
    end_frame(&mut d, counters(&mut rng));
    m.write_ok(
        &mut d,
        offset::CONTROL,
        bits::CONTROL_CLEAR | bits::CONTROL_IRQ_ENABLE,
    )
    .unwrap();
    for off in [
        offset::FRAME_COUNT,
        offset::CLUSTERS,
        offset::PROVISIONAL,
        offset::UNLABELLED,
        offset::FRAME_FLAGS,
        offset::JOINS,
        offset::GEAR_STALLS,
        offset::STATUS,
    ] {
        assert_eq!(m.read(&mut d, off).unwrap(), 0, "{off:#05x} after CLEAR");
    }
    assert_eq!(
        m.read(&mut d, offset::CONTROL).unwrap(),
        bits::CONTROL_IRQ_ENABLE
    );
    assert_eq!(d.idle().irq, 0);
}

const RUN_REGS: [u32; 7] = [
    offset::RUN_K,
    offset::RUN_TH_H,
    offset::RUN_TH_V,
    offset::RUN_ROWS,
    offset::RUN_COLS,
    offset::RUN_SLOPE_H,
    offset::RUN_SLOPE_V,
];

/// What software should read back, kept beside the model.
#[derive(Default)]
struct RefRegs {
    irq_en: bool,
    done: bool,
    count: u32,
    last: RegsIn,
    /// ERROR bits.
    err: u32,
    /// Values written to the run registers and accepted (else power-on).
    run: std::collections::HashMap<u32, u32>,
}

impl RefRegs {
    fn read(&self, p: &FccParams, off: u32, idle: bool) -> u32 {
        let c = &self.last;
        if let Some(v) = self.run.get(&off) {
            return *v;
        }
        match off {
            offset::ERROR => self.err,
            offset::CONTROL => u32::from(self.irq_en) << 1,
            offset::STATUS => u32::from(self.done) | (u32::from(idle) << 1),
            offset::FRAME_COUNT => self.count,
            offset::CLUSTERS => u32::from(c.clusters),
            offset::PROVISIONAL => u32::from(c.provisional),
            offset::UNLABELLED => c.unlabelled,
            offset::FRAME_FLAGS => u32::from(c.overflow) | (u32::from(c.frame_error) << 1),
            offset::JOINS => c.joins,
            offset::GEAR_STALLS => c.gear_stalls,
            _ => regmap::registers(p)
                .iter()
                .find(|r| r.offset == off)
                .map_or(0, |r| r.reset),
        }
    }

    fn write(&mut self, off: u32, v: u32) {
        match off {
            offset::CONTROL => {
                self.irq_en = v & bits::CONTROL_IRQ_ENABLE != 0;
                if v & bits::CONTROL_CLEAR != 0 {
                    self.done = false;
                    self.count = 0;
                    self.last = RegsIn::default();
                }
            }
            offset::STATUS if v & bits::STATUS_FRAME_DONE != 0 => self.done = false,
            offset::ERROR => self.err &= !v,
            _ => {}
        }
    }

    fn write_run(&mut self, p: &FccParams, off: u32, v: u32) {
        if regmap::run_value_ok(p, off, v) {
            self.run.insert(off, v);
        } else if let Some(b) = regmap::run_error_bit(off) {
            self.err |= b;
        }
    }
}

/// A value for the run register `off`: mostly near the ends of its range
/// (both sides), sometimes anything.
fn run_value(p: &FccParams, off: u32, rng: &mut ChaCha8Rng) -> u32 {
    let r = regmap::run_range(p, off).unwrap();
    match rng.gen_range(0..4) {
        0 => rng.gen(),
        1 => r.min.saturating_sub(rng.gen_range(0..2)),
        2 => r.max + rng.gen_range(0..2),
        _ => rng.gen_range(r.min..=r.max),
    }
}

#[test]
fn seeded_random_accesses_match_the_reference_map() {
    let p = FccParams::default();
    let offsets: Vec<u32> = regmap::registers(&p)
        .iter()
        .map(|r| r.offset)
        .chain([0x028, 0x04c, 0x100, 0xffc])
        .collect();
    for seed in 0..4u64 {
        let mut d = dut(&p);
        let mut m = AxilMaster::new(seed);
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let mut r = RefRegs::default();
        for step in 0..400 {
            m.stall = [0.0, 0.3, 0.8][rng.gen_range(0..3)];
            m.order = match rng.gen_range(0..3) {
                0 => WriteOrder::Together,
                1 => WriteOrder::AwFirst(rng.gen_range(1..4)),
                _ => WriteOrder::WFirst(rng.gen_range(1..4)),
            };
            d.live.idle_next = rng.gen::<u8>() & 1;
            d.idle();
            let off = offsets[rng.gen_range(0..offsets.len())];
            match rng.gen_range(0..10) {
                0..=3 => {
                    let got = m.read(&mut d, off).unwrap();
                    let want = r.read(&p, off, d.live.idle_next != 0);
                    assert_eq!(
                        got, want,
                        "step {step}: read {off:#05x}: expected {want:#x} != got {got:#x} (seed {seed})"
                    );
                }
                4..=6 if RUN_REGS.contains(&off) => {
                    let v = run_value(&p, off, &mut rng);
                    m.write_ok(&mut d, off, v).unwrap();
                    r.write_run(&p, off, v);
                }
                4..=6 => {
                    // Soft reset is left to its own test: keep the model simple.
                    let v = rng.gen::<u32>() & !bits::CONTROL_SOFT_RESET;
                    m.write_ok(&mut d, off, v).unwrap();
                    r.write(off, v);
                }
                _ => {
                    let c = counters(&mut rng);
                    end_frame(&mut d, c);
                    r.done = true;
                    r.count += 1;
                    r.last = c;
                }
            }
            let irq = d.idle().irq != 0;
            assert_eq!(irq, r.done && r.irq_en, "step {step}: irq (seed {seed})");
        }
    }
}

/// The active copy the core sees: -(tH^2 + 1) and -tV^2 as 36-bit two's
/// complement.
fn addends(th_h: u32, th_v: u32) -> (u64, u64) {
    let m = (1u64 << 36) - 1;
    let h = u64::from(th_h).pow(2);
    let v = u64::from(th_v).pow(2);
    ((!h) & m, (1u64 << 36).wrapping_sub(v) & m)
}

/// The squared slope the core sees: `A^2 >> 8` (spec §2).
fn slope_sq(a: u32) -> u32 {
    ((u64::from(a) * u64::from(a)) >> 8) as u32
}

type Active = (u8, u64, u64, u8, u16, u32, u32);

fn active(o: &fcc_sim::RegsOut) -> Active {
    (
        o.run_k,
        o.run_th_h_c,
        o.run_th_v_c,
        o.run_rows,
        o.run_cols,
        o.run_sl_h,
        o.run_sl_v,
    )
}

#[test]
fn run_registers_power_on_to_the_build_and_reach_the_core_only_while_idle() {
    for p in builds() {
        let mut d = dut(&p);
        let mut m = AxilMaster::new(6);
        let (h, v) = addends(p.th_h_q() as u32, p.th_v_q() as u32);
        let (sh, sv) = (p.th_h_slope_sq() as u32, p.th_v_slope_sq() as u32);
        let build = (p.fsize as u8, h, v, p.rows as u8, p.cols as u16, sh, sv);
        assert_eq!(active(&d.idle()), build, "power-on active values");
        assert_eq!(
            m.read(&mut d, offset::RUN_SLOPE_V).unwrap(),
            p.th_v_slope_q() as u32
        );
        // While a frame runs (idle low) a write changes the read-back value only.
        d.live.idle_next = 0;
        let k = if p.fsize == 3 { 3 } else { p.fsize as u32 - 2 };
        m.write_ok(&mut d, offset::RUN_K, k).unwrap();
        m.write_ok(&mut d, offset::RUN_TH_H, 1).unwrap();
        m.write_ok(&mut d, offset::RUN_TH_V, 0x8000).unwrap();
        m.write_ok(&mut d, offset::RUN_SLOPE_H, 0xffff).unwrap();
        m.write_ok(&mut d, offset::RUN_SLOPE_V, 1).unwrap();
        for _ in 0..40 {
            assert_eq!(active(&d.idle()), build, "changed during a frame");
        }
        assert_eq!(m.read(&mut d, offset::RUN_K).unwrap(), k);
        assert_eq!(m.read(&mut d, offset::RUN_TH_H).unwrap(), 1);
        assert_eq!(m.read(&mut d, offset::RUN_TH_V).unwrap(), 0x8000);
        assert_eq!(m.read(&mut d, offset::RUN_SLOPE_H).unwrap(), 0xffff);
        assert_eq!(m.read(&mut d, offset::RUN_SLOPE_V).unwrap(), 1);
        // Idle again (registered from `idle_next`): taken within a cycle.
        d.live.idle_next = 1;
        d.idle();
        d.idle();
        let (h, v) = addends(1, 0x8000);
        assert_eq!(
            active(&d.idle()),
            (
                k as u8,
                h,
                v,
                p.rows as u8,
                p.cols as u16,
                slope_sq(0xffff),
                slope_sq(1)
            ),
            "taken when idle"
        );
        // Squares of every bit pattern's extremes, each written while idle.
        for (th_h, th_v) in [(0x7fff, 0x5555), (0x0101, 0x00ff), (128, 256)] {
            m.write_ok(&mut d, offset::RUN_TH_H, th_h).unwrap();
            m.write_ok(&mut d, offset::RUN_TH_V, th_v).unwrap();
            d.idle();
            let o = d.idle();
            assert_eq!(
                (o.run_th_h_c, o.run_th_v_c),
                addends(th_h, th_v),
                "squares of {th_h:#x}, {th_v:#x}"
            );
        }
        for (a_h, a_v) in [(0x8000, 0x00ff), (0x0010, 0x0f0f), (0, 0x7ffe)] {
            m.write_ok(&mut d, offset::RUN_SLOPE_H, a_h).unwrap();
            m.write_ok(&mut d, offset::RUN_SLOPE_V, a_v).unwrap();
            d.idle();
            let o = d.idle();
            assert_eq!(
                (o.run_sl_h, o.run_sl_v),
                (slope_sq(a_h), slope_sq(a_v)),
                "squared slopes of {a_h:#x}, {a_v:#x}"
            );
        }
        // A power-on reset restores the build's values.
        d.reset(1);
        d.idle();
        assert_eq!(active(&d.idle()), build, "after rst");
        assert_eq!(m.read(&mut d, offset::RUN_K).unwrap(), p.fsize as u32);
    }
}

#[test]
fn refused_run_writes_keep_the_old_value_and_set_their_error_bit() {
    for p in builds() {
        let mut d = dut(&p);
        let mut m = AxilMaster::new(7);
        d.live.idle_next = 1;
        let kmax = p.fsize as u32;
        let bad: Vec<(u32, Vec<u32>)> = vec![
            (
                offset::RUN_K,
                vec![0, 1, 2, 4, kmax + 1, kmax + 2, 13, 0x103, u32::MAX],
            ),
            (offset::RUN_TH_H, vec![0, 0x8001, 0x1_0000, u32::MAX]),
            (offset::RUN_TH_V, vec![0, 0x8001, 0x1_0001, 0x8000_0001]),
            (
                offset::RUN_ROWS,
                vec![0, p.rows as u32 + 1, 255, 0x100 + p.rows as u32],
            ),
            (
                offset::RUN_COLS,
                vec![
                    0,
                    regmap::RUN_COLS_MIN - 1,
                    p.cols as u32 + 1,
                    8191,
                    0x1_0000 + p.cols as u32,
                ],
            ),
            (offset::RUN_SLOPE_H, vec![0x1_0000, 0x1_ffff, u32::MAX]),
            (offset::RUN_SLOPE_V, vec![0x1_0000, 0x8000_0000]),
        ];
        for (off, values) in bad {
            let bit = regmap::run_error_bit(off).unwrap();
            let before = m.read(&mut d, off).unwrap();
            let act = active(&d.idle());
            for v in values {
                assert!(!regmap::run_value_ok(&p, off, v));
                m.write_ok(&mut d, off, v).unwrap();
                let got = m.read(&mut d, off).unwrap();
                assert_eq!(got, before, "{off:#05x} <- {v:#x}: value must stay");
                let err = m.read(&mut d, offset::ERROR).unwrap();
                assert_eq!(
                    err, bit,
                    "{off:#05x} <- {v:#x}: ERROR expected {bit:#x} != got {err:#x}"
                );
                assert_eq!(
                    active(&d.idle()),
                    act,
                    "{off:#05x} <- {v:#x}: active changed"
                );
                // Writing 0 clears nothing; writing the bit clears it.
                m.write_ok(&mut d, offset::ERROR, 0).unwrap();
                assert_eq!(m.read(&mut d, offset::ERROR).unwrap(), bit);
                m.write_ok(&mut d, offset::ERROR, bit).unwrap();
                assert_eq!(m.read(&mut d, offset::ERROR).unwrap(), 0);
            }
        }
        // Valid values at both ends are taken and set no bit.
        for off in RUN_REGS {
            let r = regmap::run_range(&p, off).unwrap();
            for v in [r.min, r.max] {
                let v = if off == offset::RUN_K { v | 1 } else { v };
                m.write_ok(&mut d, off, v).unwrap();
                assert_eq!(m.read(&mut d, off).unwrap(), v, "{off:#05x} <- {v}");
            }
        }
        assert_eq!(m.read(&mut d, offset::ERROR).unwrap(), 0);
        // Errors accumulate, one bit per register.
        m.write_ok(&mut d, offset::RUN_K, 2).unwrap();
        m.write_ok(&mut d, offset::RUN_COLS, 0).unwrap();
        assert_eq!(
            m.read(&mut d, offset::ERROR).unwrap(),
            bits::ERROR_K | bits::ERROR_COLS
        );
    }
}
