//! `fcc_union_engine`: the merge table's union engine.
//!
//! A join (a, b) finds the roots of a and b in two *slots* (even, odd) that
//! own the table's read port on alternate cycles (`odd_turn`), so both walks
//! advance together, each at one step per two cycles: the word read for a
//! slot arrives exactly when its turn comes back, and the next address is the
//! word's parent (one LUT from the RAM's output register). When both roots
//! are known, the larger is linked under the smaller (the link write), and
//! the next join starts in the same cycle. The root of the previous join's
//! `a` side is kept (`kept_root`): a join with the same `a` (`join_same`)
//! starts with that side done, and its slot takes the kept root one cycle
//! later, long before the other side can finish. No path compression: the
//! joins arrive with representatives that are close to their roots.
//!
//! The engine works only while `active` (the table's Union mode); the join
//! in waiting (`next_*`) is taken from the sort network in any mode.

use crate::fcc_fanout_reg::FccFanoutReg;
use rust_hdl::prelude::*;

#[derive(LogicBlock, Default)]
pub struct FccUnionEngine {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    /// The table is in Union mode.
    pub active: Signal<In, Bit>,
    // Joins from the sort network: taken when `join_take`.
    pub join_valid: Signal<In, Bit>,
    pub join_a: Signal<In, Bits<16>>,
    pub join_b: Signal<In, Bits<16>>,
    pub join_same: Signal<In, Bit>,
    pub join_take: Signal<Out, Bit>,
    // The word read two cycles ago (forwarding applied).
    pub word_root: Signal<In, Bit>,
    pub word_parent: Signal<In, Bits<16>>,
    // Read request.
    pub read_en: Signal<Out, Bit>,
    pub read_addr: Signal<Out, Bits<16>>,
    // Link write: `T[link_addr] = link_data`, no longer a root.
    pub link_en: Signal<Out, Bit>,
    pub link_addr: Signal<Out, Bits<16>>,
    pub link_data: Signal<Out, Bits<16>>,
    /// No join held or in progress.
    pub idle: Signal<Out, Bit>,
    // The join in waiting.
    next_valid: DFF<Bit>,
    next_a: DFF<Bits<16>>,
    next_b: DFF<Bits<16>>,
    next_same: DFF<Bit>,
    // The join in progress: the two slots.
    join_busy: DFF<Bit>,
    odd_turn: FccFanoutReg<Bit>,
    walk_even: DFF<Bits<16>>,
    walk_odd: DFF<Bits<16>>,
    done_even: DFF<Bit>,
    done_odd: DFF<Bit>,
    /// The second read of the join started in the previous cycle is due.
    read_b_due: DFF<Bit>,
    /// The slot of the join started in the previous cycle takes `kept_root`.
    take_kept_root: DFF<Bit>,
    /// Address of the next read when no walk continues.
    next_read_addr: DFF<Bits<16>>,
    kept_root: DFF<Bits<16>>,
    /// A read of this engine is in flight (stage 1, 2 of the RAM latency).
    word_valid_s1: DFF<Bit>,
    word_valid_s2: DFF<Bit>,
    // Combinational.
    walk_continues: Signal<Local, Bit>,
    root_found: Signal<Local, Bit>,
    turn_done: Signal<Local, Bit>,
    other_done: Signal<Local, Bit>,
    link: Signal<Local, Bit>,
    start: Signal<Local, Bit>,
    low_root: Signal<Local, Bits<16>>,
    high_root: Signal<Local, Bits<16>>,
}

impl Logic for FccUnionEngine {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self,
            clk,
            next_valid,
            next_a,
            next_b,
            next_same,
            join_busy,
            odd_turn,
            walk_even,
            walk_odd,
            done_even,
            done_odd,
            read_b_due,
            take_kept_root,
            next_read_addr,
            kept_root,
            word_valid_s1,
            word_valid_s2
        );
        // The two roots, ordered.
        self.low_root.next = self.walk_even.q.val();
        self.high_root.next = self.walk_odd.q.val();
        if self.walk_odd.q.val() < self.walk_even.q.val() {
            self.low_root.next = self.walk_odd.q.val();
            self.high_root.next = self.walk_even.q.val();
        }
        self.odd_turn.d.next = !self.odd_turn.q.val();
        self.read_en.next = false;
        self.link_en.next = false;
        self.start.next = false;
        self.link.next = false;
        self.walk_continues.next = false;
        self.root_found.next = false;
        self.join_take.next = self.join_valid.val() & !self.next_valid.q.val();
        if self.join_take.val() {
            self.next_valid.d.next = true;
            self.next_a.d.next = self.join_a.val();
            self.next_b.d.next = self.join_b.val();
            self.next_same.d.next = self.join_same.val();
        }
        // The slot whose turn it is and the other one.
        self.turn_done.next = self.done_even.q.val();
        self.other_done.next = self.done_odd.q.val();
        if self.odd_turn.q.val() {
            self.turn_done.next = self.done_odd.q.val();
            self.other_done.next = self.done_even.q.val();
        }
        // The next address when no walk continues: a join's first read, or
        // the second read of the join started in the previous cycle.
        self.next_read_addr.d.next = self.next_a.q.val();
        if self.next_same.q.val() {
            self.next_read_addr.d.next = self.next_b.q.val();
        }
        if self.join_take.val() {
            self.next_read_addr.d.next = self.join_a.val();
            if self.join_same.val() {
                self.next_read_addr.d.next = self.join_b.val();
            }
        }
        self.read_b_due.d.next = false;
        self.take_kept_root.d.next = false;
        if self.active.val() {
            self.walk_continues.next = self.word_valid_s2.q.val() & !self.word_root.val();
            self.root_found.next = self.word_valid_s2.q.val() & self.word_root.val();
            self.link.next = self.join_busy.q.val()
                & (self.turn_done.val() | self.root_found.val())
                & self.other_done.val();
            if self.walk_continues.val() {
                // The walk goes on in this slot: read the parent now.
                self.read_en.next = true;
                if self.odd_turn.q.val() {
                    self.walk_odd.d.next = self.word_parent.val();
                } else {
                    self.walk_even.d.next = self.word_parent.val();
                }
            }
            if self.root_found.val() {
                if self.odd_turn.q.val() {
                    self.done_odd.d.next = true;
                } else {
                    self.done_even.d.next = true;
                }
            }
            if self.read_b_due.q.val() {
                self.read_en.next = true;
            }
            if self.link.val() {
                self.link_en.next = self.walk_even.q.val() != self.walk_odd.q.val();
                self.kept_root.d.next = self.low_root.val();
                self.join_busy.d.next = false;
            }
            // A join that started with the kept root: its slot takes it now.
            if self.take_kept_root.q.val() {
                if self.odd_turn.q.val() {
                    self.walk_odd.d.next = self.kept_root.q.val();
                } else {
                    self.walk_even.d.next = self.kept_root.q.val();
                }
            }
            self.start.next = self.next_valid.q.val() & (!self.join_busy.q.val() | self.link.val());
            if self.start.val() {
                self.next_valid.d.next = self.join_take.val();
                self.join_busy.d.next = true;
                self.read_en.next = true;
                // This slot reads the first word now; the other slot either
                // holds the kept root of `a` or reads `b` next cycle.
                if self.odd_turn.q.val() {
                    self.done_odd.d.next = false;
                    self.walk_odd.d.next = self.next_read_addr.q.val();
                    self.done_even.d.next = self.next_same.q.val();
                    self.walk_even.d.next = self.next_b.q.val();
                } else {
                    self.done_even.d.next = false;
                    self.walk_even.d.next = self.next_read_addr.q.val();
                    self.done_odd.d.next = self.next_same.q.val();
                    self.walk_odd.d.next = self.next_b.q.val();
                }
                self.take_kept_root.d.next = self.next_same.q.val();
                if !self.next_same.q.val() {
                    self.read_b_due.d.next = true;
                    self.next_read_addr.d.next = self.next_b.q.val();
                }
            }
        }
        self.read_addr.next = self.next_read_addr.q.val();
        if self.walk_continues.val() {
            self.read_addr.next = self.word_parent.val();
        }
        self.link_addr.next = self.high_root.val();
        self.link_data.next = self.low_root.val();
        self.word_valid_s1.d.next = self.read_en.val();
        self.word_valid_s2.d.next = self.word_valid_s1.q.val();
        self.idle.next = !self.join_busy.q.val() & !self.next_valid.q.val();
        if self.rst.val() {
            self.next_valid.d.next = false;
            self.join_busy.d.next = false;
            self.read_b_due.d.next = false;
            self.take_kept_root.d.next = false;
            self.word_valid_s1.d.next = false;
            self.word_valid_s2.d.next = false;
            // The slot phase has a reset of its own: nothing may rely on a
            // flip-flop's power-up value (4-state simulation, reset-only flows).
            self.odd_turn.d.next = false;
        }
    }
}
