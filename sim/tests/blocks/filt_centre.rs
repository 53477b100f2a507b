//! The sort filter's centre pipeline `fcc_filt_centre` alone under
//! Verilator, for every K (the minimum tree's depth sets its length),
//! against a software pipeline: a centre's run (`same_run`: same label as the
//! last labelled centre, forgotten after the frame's last centre) in S0, its
//! fields shown in S1, SM = S(L+1), SM+1 and SM+2, its ring join in SM+2;
//! the registered reset clears the valid flags, the run memory and the tree
//! stages whole. Directed runs of labels, then seeded random centres with
//! resets. A mismatch prints K, the cycle, the output, expected, got and the
//! seed.

use fcc_params::FccParams;
use fcc_rtl::BenchBlock;
use fcc_sim::{c_struct, load_plain, PlainDut};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

c_struct! {
    /// Inputs of one cycle, named as the ports: the centre's fields.
    pub struct FcIn {
        pub label: u16,
        pub col: u16,
        pub ring_a: u16,
        pub ring_b: u16,
        pub rst: u8,
        pub valid: u8,
        pub lok: u8,
        pub last: u8,
        pub ring: u8,
    }
}

c_struct! {
    /// Outputs during one cycle.
    #[derive(PartialEq, Eq)]
    pub struct FcOut {
        pub sm_c: u16,
        pub sm_col: u16,
        pub sm2_ring_a: u16,
        pub sm2_ring_b: u16,
        pub s1_valid: u8,
        pub s1_elig: u8,
        pub s1_same_run: u8,
        pub sm_valid: u8,
        pub sm_elig: u8,
        pub sm_same_run: u8,
        pub sm1_elig: u8,
        pub sm2_valid: u8,
        pub sm2_ring: u8,
        pub sm2_last: u8,
    }
}

/// A centre in one stage, with its ring join.
#[derive(Debug, Clone, Copy, Default)]
struct Stage {
    valid: bool,
    elig: bool,
    same_run: bool,
    c: u16,
    col: u16,
    last: bool,
    ring: bool,
    a: u16,
    b: u16,
}

/// The pipeline: `st[s]` is stage S`s` (1 ..= L + 3).
struct Model {
    l: usize,
    st: Vec<Stage>,
    last_label: u16,
    last_label_valid: bool,
    rst_q: bool,
}

impl Model {
    fn new(l: usize) -> Self {
        Model {
            l,
            st: vec![Stage::default(); l + 4],
            last_label: 0,
            last_label_valid: false,
            rst_q: false,
        }
    }

    /// The outputs before the clock edge, then the edge.
    fn step(&mut self, i: &FcIn) -> FcOut {
        let l = self.l;
        let (s1, sm, sm1, sm2) = (self.st[1], self.st[l + 1], self.st[l + 2], self.st[l + 3]);
        let out = FcOut {
            sm_c: sm.c,
            sm_col: sm.col,
            sm2_ring_a: sm2.a,
            sm2_ring_b: sm2.b,
            s1_valid: s1.valid as u8,
            s1_elig: s1.elig as u8,
            s1_same_run: s1.same_run as u8,
            sm_valid: sm.valid as u8,
            sm_elig: sm.elig as u8,
            sm_same_run: sm.same_run as u8,
            sm1_elig: sm1.elig as u8,
            sm2_valid: sm2.valid as u8,
            sm2_ring: sm2.ring as u8,
            sm2_last: sm2.last as u8,
        };
        let (valid, lok, last) = (i.valid != 0, i.lok != 0, i.last != 0);
        let s0 = Stage {
            valid,
            elig: valid && lok,
            same_run: self.last_label_valid && i.label == self.last_label,
            c: i.label,
            col: i.col & 0xfff,
            last,
            ring: i.ring != 0,
            a: i.ring_a,
            b: i.ring_b,
        };
        if valid && lok {
            self.last_label = i.label;
            self.last_label_valid = true;
        }
        if valid && last {
            self.last_label_valid = false;
        }
        self.st.pop();
        self.st.insert(1, s0);
        if self.rst_q {
            self.last_label_valid = false;
            for (s, stage) in self.st.iter_mut().enumerate() {
                if (2..=l).contains(&s) {
                    *stage = Stage::default();
                } else {
                    stage.valid = false;
                }
            }
        }
        self.rst_q = i.rst != 0;
        out
    }
}

fn run(fsize: usize, cycles: &[FcIn], what: &str, seed: u64) {
    let p = FccParams {
        fsize,
        ..FccParams::default()
    };
    let l = p.window_positions().next_power_of_two().trailing_zeros() as usize;
    let model =
        load_plain::<FcIn, FcOut>(BenchBlock::FiltCentre, &p).expect("centre pipeline model");
    let mut dut = PlainDut::new(model);
    let mut m = Model::new(l);
    for (t, i) in cycles.iter().enumerate() {
        let want = m.step(i);
        let got = dut.step(i);
        assert_eq!(
            got, want,
            "{what}: K = {fsize}, outputs differ at cycle {t} (input {i:?}): expected {want:?}, got {got:?}, seed {seed}"
        );
    }
}

/// A valid centre.
fn centre(label: u16, col: u16, lok: bool, last: bool) -> FcIn {
    FcIn {
        label,
        col,
        valid: 1,
        lok: lok as u8,
        last: last as u8,
        ..FcIn::default()
    }
}

#[test]
fn runs_of_labels_and_frame_ends_every_k() {
    let mut c = vec![FcIn {
        rst: 1,
        ..FcIn::default()
    }];
    c.push(FcIn::default());
    // A run of 5, an unlabelled point inside it (the run goes on), a new run,
    // the frame's last centre, the next frame starting with the same label.
    for col in 0..5 {
        c.push(centre(7, col, true, false));
    }
    c.push(centre(7, 5, false, false));
    c.push(centre(7, 6, true, false));
    c.push(FcIn::default());
    c.push(centre(9, 7, true, false));
    c.push(FcIn {
        ring: 1,
        ring_a: 0x1234,
        ring_b: 0xfedc,
        ..centre(9, 4095, true, true)
    });
    c.push(centre(9, 0, true, false));
    c.push(centre(9, 1, true, false));
    // A reset between two centres of one run.
    c.push(FcIn {
        rst: 1,
        ..centre(9, 2, true, false)
    });
    c.push(centre(9, 3, true, false));
    c.push(centre(9, 4, true, false));
    c.extend((0..20).map(|_| FcIn::default()));
    for fsize in [3, 5, 7, 9, 11] {
        run(fsize, &c, "directed", 0);
    }
}

#[test]
fn seeded_random_centres_with_resets_every_k() {
    for (n, fsize) in [3usize, 5, 7, 9, 11].into_iter().enumerate() {
        let seed = 100 + n as u64;
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let mut c = vec![FcIn {
            rst: 1,
            ..FcIn::default()
        }];
        let mut label = 1u16;
        for _ in 0..4_000 {
            if rng.gen_bool(0.2) {
                label = rng.gen_range(1..6);
            }
            c.push(FcIn {
                label,
                col: rng.gen_range(0..4096),
                ring_a: rng.gen(),
                ring_b: rng.gen(),
                rst: rng.gen_bool(0.01) as u8,
                valid: rng.gen_bool(0.8) as u8,
                lok: rng.gen_bool(0.7) as u8,
                last: rng.gen_bool(0.02) as u8,
                ring: rng.gen_bool(0.1) as u8,
            });
        }
        run(fsize, &c, "random", seed);
    }
}
