// Bench top of the cocotb test: the generated core (its module name,
// fcc_top and the configuration's suffix, is `FCC_TOP_MODULE of the
// fcc_params.vh generated beside it) with its ports passed through, and a 4-state checker that runs in the simulator every cycle
// (cheaper than sampling every output from Python).
//
// After the first reset has been released (`armed`), on every rising edge:
// * s_axis_tready, m_axis_tvalid, status_frame_done, status_idle must be 0 or 1;
// * m_axis_tdata, m_axis_tkeep, m_axis_tlast must be 0 or 1 in every bit while
//   m_axis_tvalid is high and on every cycle after the first accepted output beat;
// * every status word must be 0 or 1 in every bit on every cycle after the
//   first status_frame_done;
// * the AXI4-Lite handshakes (awready, wready, bvalid, arready, rvalid) and irq
//   must be 0 or 1; bresp while bvalid, rdata and rresp while rvalid, must be
//   0 or 1 in every bit.
// The first violation sets x_fail, names the signal in x_sig (index into
// X_NAMES of test_fcc_top.py) and its cycle in x_cycle, and is printed.
// The counters (cycle, accepted input and output beats) serve the test's
// time-outs and its reset in the middle of a frame.
`timescale 1ns / 1ps
`include "fcc_params.vh"
module fcc_bench_top (
    input  wire        clk,
    input  wire        rst,
    input  wire [63:0] s_axis_tdata,
    input  wire        s_axis_tvalid,
    output wire        s_axis_tready,
    input  wire        s_axis_tlast,
    output wire [63:0] m_axis_tdata,
    output wire [7:0]  m_axis_tkeep,
    output wire        m_axis_tvalid,
    input  wire        m_axis_tready,
    output wire        m_axis_tlast,
    output wire [15:0] status_clusters,
    output wire [15:0] status_provisional,
    output wire        status_overflow,
    output wire [19:0] status_unlabelled,
    output wire        status_frame_error,
    output wire [23:0] status_joins,
    output wire [23:0] status_gear_stalls,
    output wire        status_frame_done,
    output wire        status_idle,
    // The register file, driven by the test's AXI4-Lite master.
    input  wire [11:0] s_axil_awaddr,
    input  wire        s_axil_awvalid,
    output wire        s_axil_awready,
    input  wire [31:0] s_axil_wdata,
    input  wire [3:0]  s_axil_wstrb,
    input  wire        s_axil_wvalid,
    output wire        s_axil_wready,
    output wire [1:0]  s_axil_bresp,
    output wire        s_axil_bvalid,
    input  wire        s_axil_bready,
    input  wire [11:0] s_axil_araddr,
    input  wire        s_axil_arvalid,
    output wire        s_axil_arready,
    output wire [31:0] s_axil_rdata,
    output wire [1:0]  s_axil_rresp,
    output wire        s_axil_rvalid,
    input  wire        s_axil_rready,
    output wire        irq
);
    `FCC_TOP_MODULE core (
        .clk(clk), .rst(rst),
        .s_axis_tdata(s_axis_tdata), .s_axis_tvalid(s_axis_tvalid),
        .s_axis_tready(s_axis_tready), .s_axis_tlast(s_axis_tlast),
        .m_axis_tdata(m_axis_tdata), .m_axis_tkeep(m_axis_tkeep),
        .m_axis_tvalid(m_axis_tvalid), .m_axis_tready(m_axis_tready),
        .m_axis_tlast(m_axis_tlast),
        .status_clusters(status_clusters), .status_provisional(status_provisional),
        .status_overflow(status_overflow), .status_unlabelled(status_unlabelled),
        .status_frame_error(status_frame_error), .status_joins(status_joins),
        .status_gear_stalls(status_gear_stalls), .status_frame_done(status_frame_done),
        .status_idle(status_idle),
        .s_axil_awaddr(s_axil_awaddr), .s_axil_awvalid(s_axil_awvalid), .s_axil_awready(s_axil_awready),
        .s_axil_wdata(s_axil_wdata), .s_axil_wstrb(s_axil_wstrb), .s_axil_wvalid(s_axil_wvalid),
        .s_axil_wready(s_axil_wready),
        .s_axil_bresp(s_axil_bresp), .s_axil_bvalid(s_axil_bvalid), .s_axil_bready(s_axil_bready),
        .s_axil_araddr(s_axil_araddr), .s_axil_arvalid(s_axil_arvalid), .s_axil_arready(s_axil_arready),
        .s_axil_rdata(s_axil_rdata), .s_axil_rresp(s_axil_rresp), .s_axil_rvalid(s_axil_rvalid),
        .s_axil_rready(s_axil_rready),
        .irq(irq),
        // The source sends whole beats: every byte kept.
        .s_axis_tkeep(8'hff)
    );

    reg [31:0] cycle = 0;
    reg [31:0] in_beats = 0;
    reg [31:0] out_beats = 0;
    reg armed = 0;
    reg out_seen = 0;
    reg status_seen = 0;
    reg x_fail = 0;
    reg [4:0] x_sig = 0;
    reg [31:0] x_cycle = 0;

    // 1 when any bit of v is X or Z.
    `define FCC_HAS_X(v) (^(v) === 1'bx)
    `define FCC_CHECK(cond, idx, name, v) \
        if (!x_fail && (cond) && `FCC_HAS_X(v)) begin \
            x_fail <= 1; x_sig <= idx; x_cycle <= cycle; \
            $display("fcc_bench_top: X/Z on %s = %b at cycle %0d (%0t)", name, v, cycle, $time); \
        end

    always @(posedge clk) begin
        cycle <= cycle + 1;
        if (rst === 1'b1) begin
            armed <= 1;
        end else if (armed) begin
            `FCC_CHECK(1, 0, "s_axis_tready", s_axis_tready)
            `FCC_CHECK(1, 1, "m_axis_tvalid", m_axis_tvalid)
            `FCC_CHECK(1, 2, "status_frame_done", status_frame_done)
            `FCC_CHECK(1, 3, "status_idle", status_idle)
            `FCC_CHECK(out_seen || m_axis_tvalid === 1'b1, 4, "m_axis_tdata", m_axis_tdata)
            `FCC_CHECK(out_seen || m_axis_tvalid === 1'b1, 5, "m_axis_tkeep", m_axis_tkeep)
            `FCC_CHECK(out_seen || m_axis_tvalid === 1'b1, 6, "m_axis_tlast", m_axis_tlast)
            `FCC_CHECK(status_seen || status_frame_done === 1'b1, 7, "status_clusters", status_clusters)
            `FCC_CHECK(status_seen || status_frame_done === 1'b1, 8, "status_provisional", status_provisional)
            `FCC_CHECK(status_seen || status_frame_done === 1'b1, 9, "status_overflow", status_overflow)
            `FCC_CHECK(status_seen || status_frame_done === 1'b1, 10, "status_unlabelled", status_unlabelled)
            `FCC_CHECK(status_seen || status_frame_done === 1'b1, 11, "status_frame_error", status_frame_error)
            `FCC_CHECK(status_seen || status_frame_done === 1'b1, 12, "status_joins", status_joins)
            `FCC_CHECK(status_seen || status_frame_done === 1'b1, 13, "status_gear_stalls", status_gear_stalls)
            `FCC_CHECK(1, 14, "s_axil_awready", s_axil_awready)
            `FCC_CHECK(1, 15, "s_axil_wready", s_axil_wready)
            `FCC_CHECK(1, 16, "s_axil_bvalid", s_axil_bvalid)
            `FCC_CHECK(1, 17, "s_axil_arready", s_axil_arready)
            `FCC_CHECK(1, 18, "s_axil_rvalid", s_axil_rvalid)
            `FCC_CHECK(1, 19, "irq", irq)
            `FCC_CHECK(s_axil_bvalid === 1'b1, 20, "s_axil_bresp", s_axil_bresp)
            `FCC_CHECK(s_axil_rvalid === 1'b1, 21, "s_axil_rdata", s_axil_rdata)
            `FCC_CHECK(s_axil_rvalid === 1'b1, 22, "s_axil_rresp", s_axil_rresp)
            if (s_axis_tvalid === 1'b1 && s_axis_tready === 1'b1) in_beats <= in_beats + 1;
            if (m_axis_tvalid === 1'b1 && m_axis_tready === 1'b1) begin
                out_beats <= out_beats + 1;
                out_seen <= 1;
            end
            if (status_frame_done === 1'b1) status_seen <= 1;
        end
    end
    `undef FCC_CHECK
    `undef FCC_HAS_X
endmodule
