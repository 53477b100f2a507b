//! `FccSetPick`: the op of `FccSetQueue`'s head that goes next. An entry
//! of the queue holds a pixel slot's ops (`SetQBundle`): its run's flush
//! (a find), its run's start (a make), a join and the column's marker, any
//! of them, in that order. `part` (registered by the queue) says which
//! parts are gone already: the first part present at or after it is the
//! op (`op`, as `FccSetGate` takes it), `last` when no part follows, and
//! `after` the part after it (the next entry's first after the last).
//! Combinational.

use rust_hdl::prelude::*;

use super::fcc_set_queue::{SetQBundle, SetQOp};
use crate::types::kb;

/// Parts of an entry, in order.
pub const PART_FIND: u64 = 0;
pub const PART_MAKE: u64 = 1;
pub const PART_JOIN: u64 = 2;
pub const PART_MARK: u64 = 3;

#[derive(LogicBlock)]
pub struct FccSetPick {
    pub bundle: Signal<In, SetQBundle>,
    pub part: Signal<In, Bits<2>>,
    pub op: Signal<Out, SetQOp>,
    pub last: Signal<Out, Bit>,
    pub after: Signal<Out, Bits<2>>,
    sel_find: Signal<Local, Bit>,
    sel_make: Signal<Local, Bit>,
    sel_join: Signal<Local, Bit>,
    p_find: Constant<Bits<2>>,
    p_make: Constant<Bits<2>>,
    p_join: Constant<Bits<2>>,
    p_mark: Constant<Bits<2>>,
}

impl Default for FccSetPick {
    fn default() -> Self {
        Self {
            bundle: Default::default(),
            part: Default::default(),
            op: Default::default(),
            last: Default::default(),
            after: Default::default(),
            sel_find: Default::default(),
            sel_make: Default::default(),
            sel_join: Default::default(),
            p_find: kb(PART_FIND),
            p_make: kb(PART_MAKE),
            p_join: kb(PART_JOIN),
            p_mark: kb(PART_MARK),
        }
    }
}

impl Logic for FccSetPick {
    #[hdl_gen]
    fn update(&mut self) {
        // The first part present at or after `part`; the marker otherwise.
        self.sel_find.next = self.bundle.val().find & (self.part.val() == self.p_find.val());
        self.sel_make.next = self.bundle.val().make
            & !self.sel_find.val()
            & (self.part.val() != self.p_join.val())
            & (self.part.val() != self.p_mark.val());
        self.sel_join.next = self.bundle.val().join
            & !self.sel_find.val()
            & !self.sel_make.val()
            & (self.part.val() != self.p_mark.val());
        self.op.next.make = self.sel_make.val();
        self.op.next.join = self.sel_join.val();
        self.op.next.mark = !self.sel_find.val() & !self.sel_make.val() & !self.sel_join.val();
        self.op.next.ring = self.bundle.val().ring;
        // A join's: the ring check's; a find's: the frame end's flush of a
        // run held by hold 4 (a make's ring flag belongs to the make: a
        // row's first run starts with a make).
        if self.sel_join.val() {
            self.op.next.ring = self.bundle.val().seam;
        }
        if self.sel_find.val() {
            self.op.next.ring = self.bundle.val().ring & !self.bundle.val().make;
        }
        self.op.next.under = self.bundle.val().under;
        self.op.next.a = self.bundle.val().ja;
        if self.sel_find.val() {
            self.op.next.a = self.bundle.val().f;
        }
        if self.sel_make.val() {
            self.op.next.a = self.bundle.val().m;
        }
        self.op.next.b = self.bundle.val().jb;
        self.op.next.col = self.bundle.val().col;
        self.op.next.row = self.bundle.val().row;
        // What follows it.
        self.last.next = true;
        self.after.next = self.p_find.val();
        if self.sel_find.val() {
            self.last.next =
                !self.bundle.val().make & !self.bundle.val().join & !self.bundle.val().mark;
            self.after.next = self.p_make.val();
        }
        if self.sel_make.val() {
            self.last.next = !self.bundle.val().join & !self.bundle.val().mark;
            self.after.next = self.p_join.val();
        }
        if self.sel_join.val() {
            self.last.next = !self.bundle.val().mark;
            self.after.next = self.p_mark.val();
        }
        if self.last.val() {
            self.after.next = self.p_find.val();
        }
    }
}
