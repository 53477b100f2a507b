//! Every hardware block's own bench, one module a block, in one test
//! binary: linked once, and its tests run side by side (`cargo test` runs
//! a binary's tests on as many threads as there are cores), so a bench
//! simulating on one core leaves the other to the next. Run one bench by
//! its module's name: `cargo test -p fcc-sim --test blocks set_queue::`.
//! The whole core's tests (the regression, its corners, run parameters
//! and sizes, the virtual board) are test binaries of their own.

// What the column core's benches share.
mod column;

// The row-major core's blocks.
mod axil_adapter;
mod credits;
mod filt_centre;
mod frame_phase;
mod input_stage;
mod label_update;
mod merge_table;
mod point_thr;
mod regs;
mod sort_net;
mod window;
mod word_window;

// The column core's blocks.
mod acc;
mod close_order;
mod closer;
mod col_core;
mod col_dist;
mod col_flow;
mod col_front;
mod col_in;
mod col_limits;
mod col_slot_buf;
mod col_start;
mod col_table;
mod col_window;
mod flush_wait;
mod label_lists;
mod label_pool;
mod label_sets;
mod record_out;
mod rep_joins;
mod row_runs;
mod run_acc;
mod set_pack;
mod set_queue;
mod slot_records;
mod stream_fifo;
