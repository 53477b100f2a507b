//! `FccColWordSplit`: a column window word's fields on ports of their own
//! (no logic). A field of a word taken from a `Vec` of signals cannot be
//! named in `#[hdl_gen]`, a port of a `Vec` of blocks can.

use rust_hdl::prelude::*;

use super::ColWord;

#[derive(LogicBlock, Default)]
pub struct FccColWordSplit {
    pub word: Signal<In, ColWord>,
    pub x: Signal<Out, Bits<16>>,
    pub y: Signal<Out, Bits<16>>,
    pub z: Signal<Out, Bits<16>>,
    pub key: Signal<Out, Bits<16>>,
    pub cv: Signal<Out, Bits<36>>,
    pub label: Signal<Out, Bits<16>>,
}

impl Logic for FccColWordSplit {
    #[hdl_gen]
    fn update(&mut self) {
        self.x.next = self.word.val().x;
        self.y.next = self.word.val().y;
        self.z.next = self.word.val().z;
        self.key.next = self.word.val().key;
        self.cv.next = self.word.val().cv;
        self.label.next = self.word.val().label;
    }
}
