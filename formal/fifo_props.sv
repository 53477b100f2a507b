// Formal properties of one FIFO of the generated core (an `FccFifo`
// instance: the join queue's or the centre buffer's records).
//
// The module under proof, its data width and its address width come from
// the generated Verilog through formal/run.sh (macros FIFO_MOD, FIFO_W,
// FIFO_A); nothing here repeats a parameter.
//
// Environment (assumed): reset in the first cycle; the writer pushes only
// while the FIFO holds fewer than 2^FIFO_A entries (the caller's duty, see
// the FIFO's doc comment); reset may come again at any time.
//
// Proved (asserted), with a reference count of entries pushed and not yet
// taken:
// - no underflow: `valid` only while the reference count is non-zero;
// - `level` is the reference count of the cycle before (no lost or doubled
//   entry in the pointers), so it never exceeds 2^FIFO_A;
// - order and integrity: the n-th entry taken is the n-th entry pushed, for
//   a solver-chosen n.
// With FORMAL_WRONG defined, `level` is compared with the count of the same
// cycle instead, which is false (level is registered): the run must fail
// with a counterexample, showing the flow can fail.
module fifo_props (
    input wire clk,
    input wire rst,
    input wire push,
    input wire [`FIFO_W-1:0] din,
    input wire take
);
    wire valid;
    wire [`FIFO_W-1:0] dout;
    wire [`FIFO_A:0] level;
    wire ram_re, ram_we;
    wire [`FIFO_A-1:0] ram_raddr, ram_waddr;

    `FIFO_MOD dut (
        .clk(clk), .rst(rst), .push(push), .din(din), .valid(valid), .dout(dout),
        .take(take), .level(level), .ram_re(ram_re), .ram_raddr(ram_raddr),
        .ram_we(ram_we), .ram_waddr(ram_waddr)
    );

    localparam CAP = 1 << `FIFO_A;

    reg first = 1'b1;
    reg past_rst = 1'b1;
    reg [`FIFO_A+1:0] count = 0;
    reg [`FIFO_A+1:0] past_count = 0;
    reg [15:0] pushes = 0;
    reg [15:0] takes = 0;
    (* anyconst *) reg [15:0] pick;
    reg picked = 1'b0;
    reg [`FIFO_W-1:0] picked_data = 0;

    always @(*) begin
        if (first) assume (rst);
        if (push) assume (count < CAP);
    end

    always @(posedge clk) begin
        first <= 1'b0;
        past_rst <= rst;
        past_count <= count;
        if (rst) begin
            count <= 0;
            pushes <= 0;
            takes <= 0;
            picked <= 1'b0;
        end else begin
            count <= count + push - (valid & take);
            if (push) pushes <= pushes + 1;
            if (valid & take) takes <= takes + 1;
            if (push && pushes == pick) begin
                picked <= 1'b1;
                picked_data <= din;
            end
        end
    end

    always @(*) begin
        if (!first && !past_rst) begin
            if (valid) assert (count != 0);
`ifdef FORMAL_WRONG
            assert (level == count);
`else
            assert (level == past_count);
`endif
            assert (count <= CAP);
            if (!rst && valid && take && takes == pick) begin
                assert (picked);
                assert (dout == picked_data);
            end
        end
    end
endmodule
