//! The boards the generator writes a block design for, one row of the
//! table each, and their processing systems.

use super::vlnv;

/// A board the generator writes a block design for.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Board {
    /// Xilinx ZC706: XC7Z045-2, the default.
    #[default]
    Zc706,
    /// Avnet/Digilent ZedBoard: XC7Z020-1.
    Zedboard,
    /// TUL PYNQ-Z2: XC7Z020-1.
    PynqZ2,
    /// Xilinx ZCU104: XCZU7EV-2 (Zynq UltraScale+ MPSoC).
    Zcu104,
}

/// The processing system of a board.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Ps {
    /// Zynq-7000: `processing_system7`.
    Ps7,
    /// Zynq UltraScale+ MPSoC: `zynq_ultra_ps_e`.
    ZynqUltra,
}

/// Everything the scripts need to know about one board: one row of the
/// table, [`Board::info`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BoardInfo {
    /// `fcc gen --board` name.
    pub name: &'static str,
    /// Name for people.
    pub title: &'static str,
    /// The device.
    pub part: &'static str,
    /// Vivado board part (board files).
    pub board_part: &'static str,
    pub ps: Ps,
    /// Device family as IP-XACT names it (`supported_families`).
    pub family: &'static str,
    /// Highest clock of the design: the lower of the PS's fabric clock
    /// limit and the AXI DMA's characterised Fmax on this part, MHz.
    pub clock_max_mhz: f64,
    /// Where [`Self::clock_max_mhz`] comes from.
    pub clock_max_source: &'static str,
    /// Block design name (and its project's and wrapper's).
    pub bd_name: &'static str,
    /// Block design script.
    pub bd_script: &'static str,
    /// Bare-metal C example.
    pub example: &'static str,
}

/// Every board, in `--board` order.
pub const BOARDS: [Board; 4] = [Board::Zc706, Board::Zedboard, Board::PynqZ2, Board::Zcu104];

impl Board {
    /// The board's row of the table.
    pub fn info(self) -> BoardInfo {
        match self {
            Board::Zc706 => BoardInfo {
                name: "zc706",
                title: "ZC706",
                part: "xc7z045ffg900-2",
                board_part: "xilinx.com:zc706:part0:1.4",
                ps: Ps::Ps7,
                family: "zynq",
                clock_max_mhz: 240.0,
                clock_max_source: "AXI DataMover (the AXI DMA's engine), PG022 Maximum Frequencies: Kintex-7 -2 240 MHz (the Z-7045 fabric); the PS7 FCLK limit is 250 MHz",
                bd_name: "fcc_zc706",
                bd_script: "fcc_zc706_bd.tcl",
                example: "fcc_zc706_example.c",
            },
            Board::Zedboard => BoardInfo {
                name: "zedboard",
                title: "ZedBoard",
                part: "xc7z020clg484-1",
                board_part: "avnet.com:zedboard:part0:1.4",
                ps: Ps::Ps7,
                family: "zynq",
                clock_max_mhz: 150.0,
                clock_max_source: "AXI DataMover (the AXI DMA's engine), PG022 Maximum Frequencies: Artix-7 -1 150 MHz (the Z-7020 fabric)",
                bd_name: "fcc_zedboard",
                bd_script: "fcc_zedboard_bd.tcl",
                example: "fcc_zedboard_example.c",
            },
            Board::PynqZ2 => BoardInfo {
                name: "pynq-z2",
                title: "PYNQ-Z2",
                part: "xc7z020clg400-1",
                board_part: "tul.com.tw:pynq-z2:part0:1.0",
                ps: Ps::Ps7,
                family: "zynq",
                clock_max_mhz: 150.0,
                clock_max_source: "AXI DataMover (the AXI DMA's engine), PG022 Maximum Frequencies: Artix-7 -1 150 MHz (the Z-7020 fabric)",
                bd_name: "fcc_pynq_z2",
                bd_script: "fcc_pynq_z2_bd.tcl",
                example: "fcc_pynq_z2_example.c",
            },
            Board::Zcu104 => BoardInfo {
                name: "zcu104",
                title: "ZCU104",
                part: "xczu7ev-ffvc1156-2-e",
                board_part: "xilinx.com:zcu104:part0:1.1",
                ps: Ps::ZynqUltra,
                family: "zynquplus",
                clock_max_mhz: 250.0,
                clock_max_source: "not characterised here: PG022's table lists 7-series families only; 250 MHz is this generator's assumption for the -2 UltraScale+ fabric, to be confirmed on the board",
                bd_name: "fcc_zcu104",
                bd_script: "fcc_zcu104_bd.tcl",
                example: "fcc_zcu104_example.c",
            },
        }
    }

    /// The board of a `--board` name.
    pub fn from_name(name: &str) -> Result<Board, String> {
        BOARDS
            .into_iter()
            .find(|b| b.info().name == name)
            .ok_or_else(|| {
                let names: Vec<&str> = BOARDS.iter().map(|b| b.info().name).collect();
                format!("unknown board '{name}'; choose one of {}", names.join(", "))
            })
    }
}

/// The PS side of a block design: IP, pins and settings of one PS flavour.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct PsInfo {
    pub vlnv: &'static str,
    pub automation_rule: &'static str,
    pub automation_config: &'static str,
    /// The fabric clock, its reset (active low), the control master and
    /// its clock pin, the memory slave and its clock pin, the interrupt input.
    pub clock: &'static str,
    pub reset: &'static str,
    pub master: &'static str,
    pub master_clock: &'static str,
    pub slave: &'static str,
    pub slave_clock: &'static str,
    pub irq: &'static str,
    /// CONFIG properties that enable the master, the slave, the
    /// interrupts, and set the fabric clock (`@FCLK@`).
    pub config: &'static str,
    /// The property that reads back the fabric clock the PS got.
    pub actual_clock: &'static str,
    /// GIC interrupt ID of `irq` bit 0.
    pub gic_base: u32,
    /// Address width the DMA needs to reach the PS's DDR.
    pub dma_addr_width: u32,
}

impl Ps {
    pub fn info(self) -> PsInfo {
        match self {
            Ps::Ps7 => PsInfo {
                vlnv: vlnv::PS7,
                automation_rule: vlnv::PS7_AUTOMATION,
                automation_config: r#"{make_external "FIXED_IO, DDR" apply_board_preset "1" Master "Disable" Slave "Disable"}"#,
                clock: "FCLK_CLK0",
                reset: "FCLK_RESET0_N",
                master: "M_AXI_GP0",
                master_clock: "M_AXI_GP0_ACLK",
                slave: "S_AXI_HP0",
                slave_clock: "S_AXI_HP0_ACLK",
                irq: "IRQ_F2P",
                config: "    CONFIG.PCW_USE_M_AXI_GP0 {1} \\\n    CONFIG.PCW_USE_S_AXI_HP0 {1} \\\n    CONFIG.PCW_USE_FABRIC_INTERRUPT {1} \\\n    CONFIG.PCW_IRQ_F2P_INTR {1} \\\n    CONFIG.PCW_FPGA0_PERIPHERAL_FREQMHZ {@FCLK@} \\\n",
                actual_clock: "CONFIG.PCW_ACT_FPGA0_PERIPHERAL_FREQMHZ",
                gic_base: 61,
                dma_addr_width: 32,
            },
            Ps::ZynqUltra => PsInfo {
                vlnv: vlnv::ZYNQ_ULTRA,
                automation_rule: vlnv::ZYNQ_ULTRA_AUTOMATION,
                automation_config: r#"{apply_board_preset "1"}"#,
                clock: "pl_clk0",
                reset: "pl_resetn0",
                master: "M_AXI_HPM0_FPD",
                master_clock: "maxihpm0_fpd_aclk",
                slave: "S_AXI_HP0_FPD",
                slave_clock: "saxihp0_fpd_aclk",
                irq: "pl_ps_irq0",
                config: "    CONFIG.PSU__USE__M_AXI_GP0 {1} \\\n    CONFIG.PSU__USE__M_AXI_GP1 {0} \\\n    CONFIG.PSU__USE__S_AXI_GP2 {1} \\\n    CONFIG.PSU__USE__IRQ0 {1} \\\n    CONFIG.PSU__FPGA_PL0_ENABLE {1} \\\n    CONFIG.PSU__CRL_APB__PL0_REF_CTRL__FREQMHZ {@FCLK@} \\\n",
                actual_clock: "CONFIG.PSU__CRL_APB__PL0_REF_CTRL__ACT_FREQMHZ",
                gic_base: 121,
                dma_addr_width: 40,
            },
        }
    }
}
