//! The register file's bus adapter alone: every writable register of the
//! map gets exactly one write-enable pulse with the held data, in every
//! order of AW and W and under BREADY stalls; writes to other offsets are
//! performed with no enable; `hold` delays a write, `defer` moves its
//! response to `done`; a read registers its word address and returns the
//! multiplexer's word two cycles after the handshake; `read_block` keeps
//! ARREADY low.

use fcc_params::FccParams;
use fcc_rtl::regmap::{offset, writable_offsets};
use fcc_sim::{load_axil_adapter, AdIn, AxilAdapterDut, AxilMaster, WriteOrder};

fn dut(p: &FccParams) -> AxilAdapterDut {
    let model = load_axil_adapter(p).unwrap_or_else(|e| panic!("{e}"));
    let mut d = AxilAdapterDut::new(model, p);
    d.reset(2);
    d.trace.clear();
    d
}

/// The cycles of `d`'s trace in which a write was performed, each with the
/// indices of the write-enables high and the held data.
fn writes(d: &AxilAdapterDut) -> Vec<(Vec<usize>, u32)> {
    d.trace
        .iter()
        .filter(|(o, _)| o.wr != 0)
        .map(|(o, we)| {
            let on = we
                .iter()
                .enumerate()
                .filter(|(_, w)| **w != 0)
                .map(|(i, _)| i)
                .collect();
            (on, o.wdata)
        })
        .collect()
}

#[test]
fn each_writable_register_gets_one_enable_with_the_held_data() {
    let p = FccParams::default();
    let offs = writable_offsets(&p);
    assert!(offs.contains(&offset::CONTROL) && offs.contains(&offset::RUN_COLS));
    for (seed, order) in [
        (1, WriteOrder::Together),
        (2, WriteOrder::AwFirst(3)),
        (3, WriteOrder::WFirst(3)),
    ] {
        let mut d = dut(&p);
        let mut m = AxilMaster::new(seed);
        m.order = order;
        m.stall = 0.5;
        for (i, off) in offs.iter().enumerate() {
            d.trace.clear();
            let data = 0x5a00_0000 | ((i as u32) << 8) | seed as u32;
            m.write_ok(&mut d, *off, data)
                .unwrap_or_else(|e| panic!("{order:?}: {e}"));
            let w = writes(&d);
            assert_eq!(
                w,
                vec![(vec![i], data)],
                "{order:?} write to {off:#05x} (enable {i}): expected != got"
            );
        }
    }
}

#[test]
fn writes_to_read_only_or_unmapped_offsets_enable_nothing() {
    let p = FccParams::default();
    let mut d = dut(&p);
    let mut m = AxilMaster::new(4);
    for off in [offset::ID, offset::FRAME_COUNT, 0x3fc] {
        d.trace.clear();
        m.write_ok(&mut d, off, 0xffff_ffff)
            .unwrap_or_else(|e| panic!("{off:#05x}: {e}"));
        assert_eq!(
            writes(&d),
            vec![(vec![], 0xffff_ffff)],
            "write to {off:#05x}"
        );
    }
}

/// Offer AW and W together until both are taken, with the live inputs.
fn offer_write(d: &mut AxilAdapterDut, off: u32, data: u32) {
    let (mut aw, mut w) = (false, false);
    for _ in 0..10 {
        if aw && w {
            return;
        }
        let inp = AdIn {
            s_axil_awaddr: off,
            s_axil_awvalid: u8::from(!aw),
            s_axil_wdata: data,
            s_axil_wvalid: u8::from(!w),
            s_axil_bready: 1,
            ..d.live
        };
        let (o, _) = d.step(&inp);
        aw |= o.s_axil_awready != 0;
        w |= o.s_axil_wready != 0;
    }
    panic!("AW and W not taken");
}

#[test]
fn hold_delays_the_write_and_defer_answers_it_on_done() {
    let p = FccParams::default();
    let offs = writable_offsets(&p);
    let mut d = dut(&p);
    d.live.hold = 1;
    offer_write(&mut d, offs[0], 7);
    for c in 0..8 {
        let (o, we) = d.idle();
        assert!(o.wr == 0 && o.s_axil_bvalid == 0, "cycle {c} under hold");
        assert!(we.iter().all(|w| *w == 0), "cycle {c} under hold");
        assert!(
            o.s_axil_awready == 0 && o.s_axil_wready == 0,
            "cycle {c}: both held"
        );
    }
    // Released: performed in the next cycle, deferred, answered on `done`.
    d.live.hold = 0;
    d.live.defer = 1;
    let (o, we) = d.idle();
    assert!(o.wr == 1 && we[0] == 1, "the held write after hold falls");
    d.live.defer = 0;
    for c in 0..5 {
        let (o, _) = d.idle();
        assert_eq!(o.s_axil_bvalid, 0, "cycle {c} of a deferred write");
        assert_eq!(
            o.s_axil_awready & o.s_axil_wready,
            1,
            "cycle {c}: ready again"
        );
    }
    d.live.done = 1;
    let (o, _) = d.idle();
    assert_eq!(o.s_axil_bvalid, 0, "B rises the cycle after done");
    d.live.done = 0;
    let (o, _) = d.idle();
    assert_eq!((o.s_axil_bvalid, o.s_axil_bresp), (1, 0), "OKAY after done");
}

#[test]
fn read_returns_the_word_two_cycles_after_the_handshake() {
    let p = FccParams::default();
    let mut d = dut(&p);
    let mut m = AxilMaster::new(5);
    m.stall = 0.5;
    for (i, off) in [0x000u32, 0x044, 0x090, 0xffc, 0x3f0]
        .into_iter()
        .enumerate()
    {
        d.live.read_data = 0xc0de_0000 | i as u32;
        d.trace.clear();
        let got = m
            .read(&mut d, off)
            .unwrap_or_else(|e| panic!("{off:#05x}: {e}"));
        assert_eq!(got, d.live.read_data, "read of {off:#05x}: expected != got");
        let word = (off >> 2) as u16;
        let last = d.trace.last().expect("a trace").0;
        assert_eq!(
            (last.raddr, last.raddr_hi),
            (word, word),
            "address of {off:#05x}"
        );
        let take = d
            .trace
            .iter()
            .position(|(o, _)| o.s_axil_arready != 0)
            .expect("the AR handshake");
        let first_valid = d
            .trace
            .iter()
            .position(|(o, _)| o.s_axil_rvalid != 0)
            .expect("RVALID");
        assert_eq!(
            first_valid - take,
            2,
            "read of {off:#05x}: cycles to RVALID"
        );
    }
}

#[test]
fn read_block_keeps_arready_low() {
    let p = FccParams::default();
    let mut d = dut(&p);
    d.live.read_block = 1;
    for c in 0..4 {
        let inp = AdIn {
            s_axil_araddr: 0x044,
            s_axil_arvalid: 1,
            s_axil_rready: 1,
            ..d.live
        };
        let (o, _) = d.step(&inp);
        assert!(o.s_axil_arready == 0 && o.s_axil_rvalid == 0, "cycle {c}");
    }
    d.live.read_block = 0;
    let mut m = AxilMaster::new(6);
    d.live.read_data = 0x1234_5678;
    assert_eq!(m.read(&mut d, 0x044).unwrap(), 0x1234_5678);
}
