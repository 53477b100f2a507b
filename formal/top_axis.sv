// AXI4-Stream properties of both stream ports of the generated core.
//
// The core's module name and port widths come from the generated Verilog
// through formal/run.sh (macros TOP_MOD, S_DW, S_KW, M_DW, M_KW, AW, DW);
// nothing here repeats a parameter.
//
// Environment (assumed): reset in the first cycle (and at any time later);
// the source follows AXI4-Stream: tvalid low in reset, once high it stays
// high with tdata, tkeep and tlast stable until the core takes the beat;
// the sink's tready is free (any value, any cycle), as AXI4-Stream allows;
// the AXI4-Lite port is idle.
//
// Proved (asserted) on the output port: tvalid low in the cycle after a
// reset; once high, tvalid stays high and tdata, tkeep and tlast stay stable
// until the sink takes the beat.
module top_axis (
    input wire clk,
    input wire rst,
    input wire [`S_DW-1:0] s_axis_tdata,
    input wire [`S_KW-1:0] s_axis_tkeep,
    input wire s_axis_tvalid,
    input wire s_axis_tlast,
    input wire m_axis_tready
);
    wire s_axis_tready;
    wire [`M_DW-1:0] m_axis_tdata;
    wire [`M_KW-1:0] m_axis_tkeep;
    wire m_axis_tvalid, m_axis_tlast;

    `TOP_MOD dut (
        .clk(clk), .rst(rst),
        .s_axis_tdata(s_axis_tdata), .s_axis_tkeep(s_axis_tkeep),
        .s_axis_tvalid(s_axis_tvalid), .s_axis_tready(s_axis_tready),
        .s_axis_tlast(s_axis_tlast),
        .m_axis_tdata(m_axis_tdata), .m_axis_tkeep(m_axis_tkeep),
        .m_axis_tvalid(m_axis_tvalid), .m_axis_tready(m_axis_tready),
        .m_axis_tlast(m_axis_tlast),
        .s_axil_awaddr({`AW{1'b0}}), .s_axil_awvalid(1'b0),
        .s_axil_wdata({`DW{1'b0}}), .s_axil_wstrb({(`DW/8){1'b0}}), .s_axil_wvalid(1'b0),
        .s_axil_bready(1'b1),
        .s_axil_araddr({`AW{1'b0}}), .s_axil_arvalid(1'b0), .s_axil_rready(1'b1)
    );

    reg first = 1'b1;
    reg past_rst = 1'b1;
    reg past_s_wait = 1'b0;
    reg [`S_DW-1:0] past_s_tdata = 0;
    reg [`S_KW-1:0] past_s_tkeep = 0;
    reg past_s_tlast = 1'b0;
    reg past_m_wait = 1'b0;
    reg [`M_DW-1:0] past_m_tdata = 0;
    reg [`M_KW-1:0] past_m_tkeep = 0;
    reg past_m_tlast = 1'b0;

    always @(posedge clk) begin
        first <= 1'b0;
        past_rst <= rst;
        past_s_wait <= !rst && s_axis_tvalid && !s_axis_tready;
        past_s_tdata <= s_axis_tdata;
        past_s_tkeep <= s_axis_tkeep;
        past_s_tlast <= s_axis_tlast;
        past_m_wait <= !rst && m_axis_tvalid && !m_axis_tready;
        past_m_tdata <= m_axis_tdata;
        past_m_tkeep <= m_axis_tkeep;
        past_m_tlast <= m_axis_tlast;
    end

    // The source.
    always @(*) begin
        if (first) assume (rst);
        if (rst) assume (!s_axis_tvalid);
        if (!rst && past_s_wait) begin
            assume (s_axis_tvalid);
            assume (s_axis_tdata == past_s_tdata);
            assume (s_axis_tkeep == past_s_tkeep);
            assume (s_axis_tlast == past_s_tlast);
        end
    end

    // The core's output.
    always @(*) begin
        if (!first && past_rst) assert (!m_axis_tvalid);
        if (!first && !rst && past_m_wait) begin
            assert (m_axis_tvalid);
            assert (m_axis_tdata == past_m_tdata);
            assert (m_axis_tkeep == past_m_tkeep);
            assert (m_axis_tlast == past_m_tlast);
        end
    end
endmodule
