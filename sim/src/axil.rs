//! An AXI4-Lite master for the benches: single writes and reads with the
//! address and data channels in any order and random BREADY / RREADY stalls.

use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

use crate::SimError;

/// What the master drives in one cycle.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct AxilM {
    pub awaddr: u32,
    pub awvalid: bool,
    pub wdata: u32,
    pub wvalid: bool,
    pub bready: bool,
    pub araddr: u32,
    pub arvalid: bool,
    pub rready: bool,
}

/// What the slave drives in one cycle (before the clock edge).
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct AxilS {
    pub awready: bool,
    pub wready: bool,
    pub bvalid: bool,
    pub bresp: u8,
    pub arready: bool,
    pub rvalid: bool,
    pub rdata: u32,
    pub rresp: u8,
}

/// The FFI input struct `$ty` of a model with an `s_axil_*` slave port,
/// driven by the master's `$m`, its other fields from `$rest`.
macro_rules! axil_inputs {
    ($ty:ident, $m:expr, $rest:expr) => {
        $ty {
            s_axil_awaddr: $m.awaddr,
            s_axil_awvalid: u8::from($m.awvalid),
            s_axil_wdata: $m.wdata,
            s_axil_wvalid: u8::from($m.wvalid),
            s_axil_bready: u8::from($m.bready),
            s_axil_araddr: $m.araddr,
            s_axil_arvalid: u8::from($m.arvalid),
            s_axil_rready: u8::from($m.rready),
            ..$rest
        }
    };
}
pub(crate) use axil_inputs;

/// The slave's side of the `s_axil_*` port in the FFI output struct `$o`.
macro_rules! axil_outputs {
    ($o:expr) => {
        $crate::axil::AxilS {
            awready: $o.s_axil_awready != 0,
            wready: $o.s_axil_wready != 0,
            bvalid: $o.s_axil_bvalid != 0,
            bresp: $o.s_axil_bresp,
            arready: $o.s_axil_arready != 0,
            rvalid: $o.s_axil_rvalid != 0,
            rdata: $o.s_axil_rdata,
            rresp: $o.s_axil_rresp,
        }
    };
}
pub(crate) use axil_outputs;

/// A design with an AXI4-Lite slave port: one call is one clock cycle.
pub trait AxilPort {
    fn axil_cycle(&mut self, m: &AxilM) -> AxilS;
}

/// Order of the write address and write data channels.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum WriteOrder {
    /// AW and W offered in the same cycle.
    Together,
    /// AW first, W `n` cycles later.
    AwFirst(u32),
    /// W first, AW `n` cycles later.
    WFirst(u32),
}

/// Cycles a single transfer may take before it is reported as hung.
pub const AXIL_TIMEOUT: u64 = 1000;

/// The bench's AXI4-Lite master.
#[derive(Debug, Clone)]
pub struct AxilMaster {
    rng: ChaCha8Rng,
    /// Probability that BREADY / RREADY is low in a cycle.
    pub stall: f64,
    pub order: WriteOrder,
    /// Seed, for messages.
    pub seed: u64,
}

impl AxilMaster {
    /// A master with no stalls, AW and W together.
    pub fn new(seed: u64) -> Self {
        AxilMaster {
            rng: ChaCha8Rng::seed_from_u64(seed),
            stall: 0.0,
            order: WriteOrder::Together,
            seed,
        }
    }

    fn ready(&mut self) -> bool {
        self.stall <= 0.0 || self.rng.gen::<f64>() >= self.stall
    }

    /// Write `data` to byte address `addr`; returns BRESP.
    pub fn write(
        &mut self,
        port: &mut impl AxilPort,
        addr: u32,
        data: u32,
    ) -> Result<u8, SimError> {
        let (da, dw) = match self.order {
            WriteOrder::Together => (0, 0),
            WriteOrder::AwFirst(n) => (0, u64::from(n)),
            WriteOrder::WFirst(n) => (u64::from(n), 0),
        };
        let (mut aw_done, mut w_done) = (false, false);
        for t in 0..AXIL_TIMEOUT {
            let m = AxilM {
                awaddr: addr,
                awvalid: !aw_done && t >= da,
                wdata: data,
                wvalid: !w_done && t >= dw,
                bready: self.ready(),
                ..Default::default()
            };
            let s = port.axil_cycle(&m);
            if s.bvalid && !(aw_done && w_done) {
                return Err(SimError::Protocol(format!(
                    "AXI4-Lite: BVALID before both AW and W of the write to {addr:#05x} (seed {})",
                    self.seed
                )));
            }
            if s.bvalid && m.bready {
                return Ok(s.bresp);
            }
            aw_done |= m.awvalid && s.awready;
            w_done |= m.wvalid && s.wready;
        }
        Err(SimError::Protocol(format!(
            "AXI4-Lite: write to {addr:#05x} got no response in {AXIL_TIMEOUT} cycles (seed {})",
            self.seed
        )))
    }

    /// Read byte address `addr`; returns (RDATA, RRESP).
    pub fn read_resp(
        &mut self,
        port: &mut impl AxilPort,
        addr: u32,
    ) -> Result<(u32, u8), SimError> {
        let mut ar_done = false;
        for _ in 0..AXIL_TIMEOUT {
            let m = AxilM {
                araddr: addr,
                arvalid: !ar_done,
                rready: self.ready(),
                ..Default::default()
            };
            let s = port.axil_cycle(&m);
            if s.rvalid && !ar_done {
                return Err(SimError::Protocol(format!(
                    "AXI4-Lite: RVALID before the read address of {addr:#05x} was taken (seed {})",
                    self.seed
                )));
            }
            if s.rvalid && m.rready {
                return Ok((s.rdata, s.rresp));
            }
            ar_done |= m.arvalid && s.arready;
        }
        Err(SimError::Protocol(format!(
            "AXI4-Lite: read of {addr:#05x} got no data in {AXIL_TIMEOUT} cycles (seed {})",
            self.seed
        )))
    }

    /// Read byte address `addr`, requiring an OKAY response.
    pub fn read(&mut self, port: &mut impl AxilPort, addr: u32) -> Result<u32, SimError> {
        let (d, resp) = self.read_resp(port, addr)?;
        if resp != 0 {
            return Err(SimError::Protocol(format!(
                "AXI4-Lite: read of {addr:#05x} answered RRESP {resp} (seed {})",
                self.seed
            )));
        }
        Ok(d)
    }

    /// Write, requiring an OKAY response.
    pub fn write_ok(
        &mut self,
        port: &mut impl AxilPort,
        addr: u32,
        data: u32,
    ) -> Result<(), SimError> {
        match self.write(port, addr, data)? {
            0 => Ok(()),
            r => Err(SimError::Protocol(format!(
                "AXI4-Lite: write to {addr:#05x} answered BRESP {r} (seed {})",
                self.seed
            ))),
        }
    }
}
