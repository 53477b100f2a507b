//! `FccRegSquared`: the storage of one run register whose core value is
//! derived by the shared squarer (`FccRegThresholds`): RUN_TH_H, RUN_TH_V
//! (an addend of the distance units, 36 bits) and RUN_SLOPE_H, RUN_SLOPE_V
//! (a squared slope `S = A^2 >> 8`, 24 bits).
//!
//! The shadow value (read back) and its derived value change together when
//! the squarer is done with a write to this register (`take`); the active
//! copy (the core's) loads the derived value in every cycle `load` is high
//! (the core waits for a frame's first pixel). `rst` resets the shadow pair,
//! `rst_act` the active copy, to the build's values (separate inputs, so
//! that each reset net drives at most 64 flip-flops).

use rust_hdl::prelude::*;

use crate::types::kb;

#[derive(LogicBlock)]
pub struct FccRegSquared<const N: usize> {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    pub rst_act: Signal<In, Bit>,
    /// The squarer finished this register's write: `a` and `val` are its.
    pub take: Signal<In, Bit>,
    /// The value written.
    pub a: Signal<In, Bits<16>>,
    /// The value derived from it (the squarer's output for this register).
    pub val: Signal<In, Bits<N>>,
    /// The core is idle: the active copy loads the derived value.
    pub load: Signal<In, Bit>,
    /// The value software reads back.
    pub shadow: Signal<Out, Bits<16>>,
    /// The derived value the core uses.
    pub active: Signal<Out, Bits<N>>,
    sh_a: DFF<Bits<16>>,
    sh_v: DFF<Bits<N>>,
    act: DFF<Bits<N>>,
    def_a: Constant<Bits<16>>,
    def_v: Constant<Bits<N>>,
}

impl<const N: usize> FccRegSquared<N> {
    /// The build's value `a` and the value derived from it, `v`.
    pub fn new(a: u32, v: u64) -> Self {
        assert!(a <= 0xffff, "register value {a:#x} in 16 bits");
        assert!(N >= 64 || v < 1 << N, "derived value {v:#x} in {N} bits");
        Self {
            clk: Default::default(),
            rst: Default::default(),
            rst_act: Default::default(),
            take: Default::default(),
            a: Default::default(),
            val: Default::default(),
            load: Default::default(),
            shadow: Default::default(),
            active: Default::default(),
            sh_a: Default::default(),
            sh_v: Default::default(),
            act: Default::default(),
            def_a: kb(u64::from(a)),
            def_v: kb(v),
        }
    }
}

impl<const N: usize> Logic for FccRegSquared<N> {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clk, sh_a, sh_v, act);
        if self.take.val() {
            self.sh_a.d.next = self.a.val();
            self.sh_v.d.next = self.val.val();
        }
        if self.load.val() {
            self.act.d.next = self.sh_v.q.val();
        }
        if self.rst.val() {
            self.sh_a.d.next = self.def_a.val();
            self.sh_v.d.next = self.def_v.val();
        }
        if self.rst_act.val() {
            self.act.d.next = self.def_v.val();
        }
        self.shadow.next = self.sh_a.q.val();
        self.active.next = self.act.q.val();
    }
}
