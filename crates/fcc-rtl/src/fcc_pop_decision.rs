//! `FccPopDecision`: how many labels the head beat takes from the gearbox
//! this cycle, and whether it then has all it needs.
//!
//! The head beat needs `need` new labels and has `taken`; the gearbox holds
//! at least one (`has_one`) or two (`has_two`). It pops one label when the
//! beat still needs any (`pop`), two when it needs at least two and two
//! wait (`pop_two`, with `pop`). `complete`: the beat has all its labels
//! once this cycle's pops land. How many it still needs (`need - taken`) is
//! decoded by equalities on the two 3-bit values (one LUT level), not by a
//! subtraction.
//!
//! The decision selects the gearbox's front registers and the beat
//! assembly's collected labels, some 80 multiplexer inputs: the label
//! updater builds it twice, one copy for each side, each from its own copies
//! of the inputs (see `fcc_label_update`), so that no decision net drives
//! more than 64 loads and synthesis cannot merge the two back into one.

use rust_hdl::prelude::*;

use crate::fcc_fanout_net::FccFanoutNet;
use crate::fcc_slot_mux::NEW_LABELS;
use crate::types::kb;

#[derive(LogicBlock)]
pub struct FccPopDecision {
    pub head_valid: Signal<In, Bit>,
    /// New labels the head beat takes from the gearbox, and has taken.
    pub need: Signal<In, Bits<3>>,
    pub taken: Signal<In, Bits<3>>,
    pub has_one: Signal<In, Bit>,
    pub has_two: Signal<In, Bit>,
    pub pop: Signal<Out, Bit>,
    pub pop_two: Signal<Out, Bit>,
    pub complete: Signal<Out, Bit>,
    /// The head beat needs 0, 1, 2, at least 2 more labels.
    needs_none: Signal<Local, Bit>,
    needs_one: Signal<Local, Bit>,
    needs_two: Signal<Local, Bit>,
    needs_two_plus: Signal<Local, Bit>,
    /// `pop` and `pop_two` still select a side's 16-bit multiplexers (up
    /// to 67 loads at K = 11): Vivado replicates their logic.
    pop_net: FccFanoutNet<Bit>,
    pop_two_net: FccFanoutNet<Bit>,
    count: Vec<Constant<Bits<3>>>,
}

impl Default for FccPopDecision {
    fn default() -> Self {
        Self {
            head_valid: Default::default(),
            need: Default::default(),
            taken: Default::default(),
            has_one: Default::default(),
            has_two: Default::default(),
            pop: Default::default(),
            pop_two: Default::default(),
            complete: Default::default(),
            needs_none: Default::default(),
            needs_one: Default::default(),
            needs_two: Default::default(),
            needs_two_plus: Default::default(),
            pop_net: Default::default(),
            pop_two_net: Default::default(),
            count: (0..=NEW_LABELS).map(|n| kb(n as u64)).collect(),
        }
    }
}

impl Logic for FccPopDecision {
    #[hdl_gen]
    fn update(&mut self) {
        self.needs_none.next = self.need.val() == self.taken.val();
        self.needs_one.next = false;
        self.needs_two.next = false;
        self.needs_two_plus.next = false;
        for k in 0..4 {
            if (self.taken.val() == self.count[k].val())
                & (self.need.val() == self.count[k + 1].val())
            {
                self.needs_one.next = true;
            }
        }
        for k in 0..3 {
            if (self.taken.val() == self.count[k].val())
                & (self.need.val() == self.count[k + 2].val())
            {
                self.needs_two.next = true;
                self.needs_two_plus.next = true;
            }
        }
        for k in 0..2 {
            if (self.taken.val() == self.count[k].val())
                & (self.need.val() == self.count[k + 3].val())
            {
                self.needs_two_plus.next = true;
            }
        }
        if (self.taken.val() == self.count[0].val()) & (self.need.val() == self.count[4].val()) {
            self.needs_two_plus.next = true;
        }
        self.pop_two_net.x.next =
            self.head_valid.val() & self.needs_two_plus.val() & self.has_two.val();
        self.pop_net.x.next = self.head_valid.val() & !self.needs_none.val() & self.has_one.val();
        self.pop_two.next = self.pop_two_net.y.val();
        self.pop.next = self.pop_net.y.val();
        self.complete.next = self.needs_none.val()
            | (self.needs_one.val() & self.has_one.val())
            | (self.needs_two.val() & self.has_two.val());
    }
}
