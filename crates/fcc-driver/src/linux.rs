//! Linux userspace backend: UIO (`uio_pdrv_genirq`, `generic-uio` nodes)
//! for the core's and the DMA's register windows and for the core's
//! interrupt, u-dma-buf for DMA memory. Only Linux system calls through
//! `libc` (no architecture-specific code): built for the board with
//! `--target armv7-unknown-linux-gnueabihf` (docs/board.md has the
//! device-tree fragment).
//!
//! The devices are found through sysfs: `/sys/class/uio/uioN/name` is the
//! device-tree node's name, `maps/map0/{addr,size}` its register window;
//! `/sys/class/u-dma-buf/NAME/{phys_addr,size}` the buffer, whose cache is
//! maintained with its `sync_*` files.

use std::fmt;
use std::fs::{File, OpenOptions};
use std::io::{Read, Write};
use std::os::unix::io::AsRawFd;
use std::path::{Path, PathBuf};
use std::sync::Arc;
use std::time::Instant;

use crate::hal::{DmaBuffer, Hal, Window, DMA_ALIGN};

/// A failure of the platform, naming the file or device.
#[derive(Debug)]
pub struct LinuxError {
    pub what: String,
    pub source: Option<std::io::Error>,
}

impl fmt::Display for LinuxError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match &self.source {
            Some(e) => write!(f, "{}: {e}", self.what),
            None => f.write_str(&self.what),
        }
    }
}

impl std::error::Error for LinuxError {}

fn err(what: impl Into<String>) -> LinuxError {
    LinuxError {
        what: what.into(),
        source: None,
    }
}

fn io_err(what: impl Into<String>) -> impl FnOnce(std::io::Error) -> LinuxError {
    let what = what.into();
    move |e| LinuxError {
        what,
        source: Some(e),
    }
}

/// A number as sysfs writes it: `0x` hexadecimal or decimal.
pub fn parse_sysfs_number(text: &str) -> Option<u64> {
    let t = text.trim();
    match t.strip_prefix("0x").or_else(|| t.strip_prefix("0X")) {
        Some(h) => u64::from_str_radix(h, 16).ok(),
        None => t.parse().ok(),
    }
}

fn read_number(path: &Path) -> Result<u64, LinuxError> {
    let text = std::fs::read_to_string(path).map_err(io_err(path.display().to_string()))?;
    parse_sysfs_number(&text).ok_or_else(|| {
        err(format!(
            "{}: not a number: {:?}",
            path.display(),
            text.trim()
        ))
    })
}

/// A UIO device as sysfs describes it.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct UioInfo {
    /// `N` of `/dev/uioN`.
    pub index: u32,
    pub name: String,
    /// Physical address and size of its first register window (map0).
    pub addr: u64,
    pub size: u64,
}

/// Find the UIO device `name` under `sysfs` (normally `/sys`): a node
/// name as in the device tree (`fcc`, `dma`), or `uioN` / `/dev/uioN`.
pub fn find_uio(sysfs: &Path, name: &str) -> Result<UioInfo, LinuxError> {
    let class = sysfs.join("class/uio");
    let direct = name.strip_prefix("/dev/").unwrap_or(name);
    let mut seen = Vec::new();
    let entries = std::fs::read_dir(&class).map_err(io_err(format!(
        "{}: no UIO devices (is uio_pdrv_genirq loaded with of_id=generic-uio?)",
        class.display()
    )))?;
    let mut dirs: Vec<PathBuf> = entries.filter_map(|e| e.ok().map(|e| e.path())).collect();
    dirs.sort();
    for dir in dirs {
        let Some(dev) = dir.file_name().and_then(|n| n.to_str()).map(str::to_string) else {
            continue;
        };
        let Some(index) = dev.strip_prefix("uio").and_then(|n| n.parse::<u32>().ok()) else {
            continue;
        };
        let node = std::fs::read_to_string(dir.join("name"))
            .map(|s| s.trim().to_string())
            .unwrap_or_default();
        if node == name || dev == direct {
            let map = dir.join("maps/map0");
            return Ok(UioInfo {
                index,
                name: node,
                addr: read_number(&map.join("addr"))?,
                size: read_number(&map.join("size"))?,
            });
        }
        seen.push(format!("{dev} ({node})"));
    }
    Err(err(format!(
        "no UIO device named {name:?} under {}; found: {}",
        class.display(),
        if seen.is_empty() {
            "none".to_string()
        } else {
            seen.join(", ")
        }
    )))
}

/// A u-dma-buf buffer as sysfs describes it.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct UdmabufInfo {
    pub name: String,
    pub phys: u64,
    pub size: u64,
    /// Its sysfs directory (the `sync_*` files).
    pub dir: PathBuf,
}

/// Find the u-dma-buf `name` (e.g. `udmabuf0`) under `sysfs`.
pub fn find_udmabuf(sysfs: &Path, name: &str) -> Result<UdmabufInfo, LinuxError> {
    let name = name.strip_prefix("/dev/").unwrap_or(name);
    for class in ["class/u-dma-buf", "class/udmabuf"] {
        let dir = sysfs.join(class).join(name);
        if dir.is_dir() {
            return Ok(UdmabufInfo {
                name: name.to_string(),
                phys: read_number(&dir.join("phys_addr"))?,
                size: read_number(&dir.join("size"))?,
                dir,
            });
        }
    }
    Err(err(format!(
        "no u-dma-buf named {name:?} under {}/class/u-dma-buf (is the u-dma-buf module loaded and the buffer in the device tree?)",
        sysfs.display()
    )))
}

/// A shared mapping of a device file.
struct Mapping {
    ptr: *mut u8,
    len: usize,
    _file: File,
}

// SAFETY: the mapping is plain memory (or device registers accessed with
// volatile operations); it is unmapped only when the last owner drops it.
unsafe impl Send for Mapping {}
unsafe impl Sync for Mapping {}

impl Mapping {
    fn new(path: &Path, len: usize) -> Result<Mapping, LinuxError> {
        let file = OpenOptions::new()
            .read(true)
            .write(true)
            .open(path)
            .map_err(io_err(path.display().to_string()))?;
        // SAFETY: a fresh shared mapping of an open file; checked below.
        let ptr = unsafe {
            libc::mmap(
                std::ptr::null_mut(),
                len,
                libc::PROT_READ | libc::PROT_WRITE,
                libc::MAP_SHARED,
                file.as_raw_fd(),
                0,
            )
        };
        if ptr == libc::MAP_FAILED {
            return Err(io_err(format!("mmap {} ({len} bytes)", path.display()))(
                std::io::Error::last_os_error(),
            ));
        }
        Ok(Mapping {
            ptr: ptr.cast(),
            len,
            _file: file,
        })
    }
}

impl Drop for Mapping {
    fn drop(&mut self) {
        // SAFETY: ptr/len are the mapping made in `new`.
        unsafe { libc::munmap(self.ptr.cast(), self.len) };
    }
}

/// A register window of a UIO device.
struct Regs {
    map: Mapping,
    dev: PathBuf,
}

impl Regs {
    fn index(&self, offset: u32) -> Result<usize, LinuxError> {
        let o = offset as usize;
        if o & 3 != 0 || o + 4 > self.map.len {
            return Err(err(format!(
                "{}: register offset {offset:#x} outside its {}-byte window",
                self.dev.display(),
                self.map.len
            )));
        }
        Ok(o / 4)
    }
}

/// A DMA buffer carved out of the u-dma-buf.
pub struct LinuxBuffer {
    map: Arc<Mapping>,
    offset: usize,
    len: usize,
    phys: u64,
}

impl DmaBuffer for LinuxBuffer {
    fn phys(&self) -> u64 {
        self.phys
    }
    fn bytes(&self) -> &[u8] {
        // SAFETY: offset + len lies inside the mapping (checked at
        // allocation), which lives as long as `self.map`; buffers never overlap.
        unsafe { std::slice::from_raw_parts(self.map.ptr.add(self.offset), self.len) }
    }
    fn bytes_mut(&mut self) -> &mut [u8] {
        // SAFETY: as in `bytes`, and `&mut self` makes the borrow unique.
        unsafe { std::slice::from_raw_parts_mut(self.map.ptr.add(self.offset), self.len) }
    }
}

/// The board through Linux: two UIO devices and a u-dma-buf.
pub struct LinuxHal {
    core: Regs,
    dma: Regs,
    irq: File,
    irq_dev: PathBuf,
    buf: UdmabufInfo,
    buf_map: Arc<Mapping>,
    next: usize,
    start: Instant,
}

impl LinuxHal {
    /// Open the core's UIO device `core` (its interrupt is the core's
    /// `irq`), the DMA's UIO device `dma` and the u-dma-buf `udmabuf`,
    /// looked up under `/sys`.
    pub fn open(core: &str, dma: &str, udmabuf: &str) -> Result<LinuxHal, LinuxError> {
        Self::open_in(Path::new("/sys"), Path::new("/dev"), core, dma, udmabuf)
    }

    /// As [`LinuxHal::open`] with other sysfs and /dev roots.
    pub fn open_in(
        sysfs: &Path,
        dev: &Path,
        core: &str,
        dma: &str,
        udmabuf: &str,
    ) -> Result<LinuxHal, LinuxError> {
        let regs = |name: &str| -> Result<(Regs, PathBuf), LinuxError> {
            let info = find_uio(sysfs, name)?;
            let path = dev.join(format!("uio{}", info.index));
            let len = usize::try_from(info.size).map_err(|_| err("UIO window too large"))?;
            Ok((
                Regs {
                    map: Mapping::new(&path, len)?,
                    dev: path.clone(),
                },
                path,
            ))
        };
        let (core, core_dev) = regs(core)?;
        let (dma, _) = regs(dma)?;
        let irq = OpenOptions::new()
            .read(true)
            .write(true)
            .open(&core_dev)
            .map_err(io_err(core_dev.display().to_string()))?;
        let buf = find_udmabuf(sysfs, udmabuf)?;
        let len = usize::try_from(buf.size).map_err(|_| err("u-dma-buf too large"))?;
        let buf_map = Arc::new(Mapping::new(&dev.join(&buf.name), len)?);
        Ok(LinuxHal {
            core,
            dma,
            irq,
            irq_dev: core_dev,
            buf,
            buf_map,
            next: 0,
            start: Instant::now(),
        })
    }

    fn regs(&self, w: Window) -> &Regs {
        match w {
            Window::Core => &self.core,
            Window::Dma => &self.dma,
        }
    }

    /// Write `offset`, `size` and `direction` (1: to the device, 2: from
    /// it) to the buffer's sync files and trigger `what`.
    fn sync(
        &self,
        what: &str,
        offset: usize,
        len: usize,
        direction: u32,
    ) -> Result<(), LinuxError> {
        for (file, v) in [
            ("sync_offset", offset.to_string()),
            ("sync_size", len.to_string()),
            ("sync_direction", direction.to_string()),
            (what, "1".to_string()),
        ] {
            let path = self.buf.dir.join(file);
            std::fs::write(&path, v).map_err(io_err(path.display().to_string()))?;
        }
        Ok(())
    }
}

impl Hal for LinuxHal {
    type Buffer = LinuxBuffer;
    type Error = LinuxError;

    fn read32(&mut self, w: Window, offset: u32) -> Result<u32, LinuxError> {
        let r = self.regs(w);
        let i = r.index(offset)?;
        // SAFETY: `i` is inside the mapped window (checked); device
        // registers need volatile, aligned 32-bit accesses.
        Ok(unsafe { std::ptr::read_volatile(r.map.ptr.cast::<u32>().add(i)) })
    }

    fn write32(&mut self, w: Window, offset: u32, value: u32) -> Result<(), LinuxError> {
        let r = self.regs(w);
        let i = r.index(offset)?;
        // SAFETY: as in `read32`.
        unsafe { std::ptr::write_volatile(r.map.ptr.cast::<u32>().add(i), value) };
        Ok(())
    }

    fn alloc_dma(&mut self, len: usize) -> Result<LinuxBuffer, LinuxError> {
        let offset = self.next.div_ceil(DMA_ALIGN) * DMA_ALIGN;
        let phys = self.buf.phys + offset as u64;
        if offset + len > self.buf_map.len || phys & (DMA_ALIGN as u64 - 1) != 0 {
            return Err(err(format!(
                "u-dma-buf {}: {len} bytes at offset {offset} do not fit its {} bytes (make it larger in the device tree: two frames of the largest size)",
                self.buf.name, self.buf_map.len
            )));
        }
        self.next = offset + len;
        Ok(LinuxBuffer {
            map: self.buf_map.clone(),
            offset,
            len,
            phys,
        })
    }

    fn cache_clean(
        &mut self,
        buf: &mut LinuxBuffer,
        offset: usize,
        len: usize,
    ) -> Result<(), LinuxError> {
        self.sync("sync_for_device", buf.offset + offset, len, 1)
    }

    fn cache_invalidate(
        &mut self,
        buf: &mut LinuxBuffer,
        offset: usize,
        len: usize,
    ) -> Result<(), LinuxError> {
        self.sync("sync_for_cpu", buf.offset + offset, len, 2)
    }

    fn wait_irq(&mut self, timeout_us: u64) -> Result<bool, LinuxError> {
        let dev = self.irq_dev.display().to_string();
        // Unmask (uio_pdrv_genirq masks the line each time it fires).
        self.irq
            .write_all(&1u32.to_ne_bytes())
            .map_err(io_err(format!("{dev}: unmask the interrupt")))?;
        let mut pfd = libc::pollfd {
            fd: self.irq.as_raw_fd(),
            events: libc::POLLIN,
            revents: 0,
        };
        let ms = timeout_us.div_ceil(1000).min(i32::MAX as u64) as libc::c_int;
        // SAFETY: one valid pollfd.
        let n = unsafe { libc::poll(&mut pfd, 1, ms) };
        if n < 0 {
            return Err(io_err(format!("{dev}: poll"))(
                std::io::Error::last_os_error(),
            ));
        }
        if n == 0 {
            return Ok(false);
        }
        let mut count = [0u8; 4];
        self.irq
            .read_exact(&mut count)
            .map_err(io_err(format!("{dev}: read the interrupt count")))?;
        Ok(true)
    }

    fn now_ns(&mut self) -> u64 {
        self.start.elapsed().as_nanos() as u64
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn tmp(name: &str) -> PathBuf {
        let d = std::env::temp_dir().join(format!("fcc-driver-{name}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&d);
        std::fs::create_dir_all(&d).unwrap();
        d
    }

    fn put(root: &Path, rel: &str, text: &str) {
        let p = root.join(rel);
        std::fs::create_dir_all(p.parent().unwrap()).unwrap();
        std::fs::write(p, text).unwrap();
    }

    #[test]
    fn sysfs_numbers_hex_and_decimal() {
        assert_eq!(parse_sysfs_number("0x43c00000\n"), Some(0x43c0_0000));
        assert_eq!(parse_sysfs_number("8388608\n"), Some(8_388_608));
        assert_eq!(parse_sysfs_number("0x"), None);
        assert_eq!(parse_sysfs_number("ten"), None);
    }

    #[test]
    fn uio_found_by_node_name_or_device_and_missing_one_lists_what_exists() {
        let root = tmp("uio");
        put(&root, "class/uio/uio0/name", "dma\n");
        put(&root, "class/uio/uio0/maps/map0/addr", "0x40400000\n");
        put(&root, "class/uio/uio0/maps/map0/size", "0x00010000\n");
        put(&root, "class/uio/uio1/name", "fcc\n");
        put(&root, "class/uio/uio1/maps/map0/addr", "0x43c00000\n");
        put(&root, "class/uio/uio1/maps/map0/size", "0x00001000\n");
        let f = find_uio(&root, "fcc").unwrap();
        assert_eq!((f.index, f.addr, f.size), (1, 0x43c0_0000, 0x1000));
        assert_eq!(find_uio(&root, "/dev/uio0").unwrap().name, "dma");
        let e = find_uio(&root, "gpio").unwrap_err().to_string();
        assert!(e.contains("uio0 (dma)") && e.contains("uio1 (fcc)"), "{e}");
        let _ = std::fs::remove_dir_all(&root);
    }

    #[test]
    fn udmabuf_address_and_size_and_a_missing_or_garbled_one() {
        let root = tmp("udmabuf");
        put(&root, "class/u-dma-buf/udmabuf0/phys_addr", "0x3f000000\n");
        put(&root, "class/u-dma-buf/udmabuf0/size", "8388608\n");
        let b = find_udmabuf(&root, "/dev/udmabuf0").unwrap();
        assert_eq!((b.phys, b.size), (0x3f00_0000, 8 << 20));
        assert!(find_udmabuf(&root, "udmabuf1")
            .unwrap_err()
            .to_string()
            .contains("no u-dma-buf named"));
        put(&root, "class/u-dma-buf/udmabuf2/phys_addr", "zz\n");
        put(&root, "class/u-dma-buf/udmabuf2/size", "1\n");
        let e = find_udmabuf(&root, "udmabuf2").unwrap_err().to_string();
        assert!(e.contains("not a number"), "{e}");
        let _ = std::fs::remove_dir_all(&root);
    }

    #[test]
    fn registers_and_buffers_through_plain_files() {
        // Files stand in for /dev/uioN and /dev/udmabuf0: mmap works on them.
        let root = tmp("hal");
        let dev = root.join("dev");
        std::fs::create_dir_all(&dev).unwrap();
        put(&root, "class/uio/uio0/name", "fcc\n");
        put(&root, "class/uio/uio0/maps/map0/addr", "0x43c00000\n");
        put(&root, "class/uio/uio0/maps/map0/size", "0x1000\n");
        put(&root, "class/uio/uio1/name", "dma\n");
        put(&root, "class/uio/uio1/maps/map0/addr", "0x40400000\n");
        put(&root, "class/uio/uio1/maps/map0/size", "0x1000\n");
        put(&root, "class/u-dma-buf/udmabuf0/phys_addr", "0x3f000000\n");
        put(&root, "class/u-dma-buf/udmabuf0/size", "4096\n");
        std::fs::write(dev.join("uio0"), vec![0u8; 4096]).unwrap();
        std::fs::write(dev.join("uio1"), vec![0u8; 4096]).unwrap();
        std::fs::write(dev.join("udmabuf0"), vec![0u8; 4096]).unwrap();
        let mut hal = LinuxHal::open_in(&root, &dev, "fcc", "dma", "udmabuf0").unwrap();
        hal.write32(Window::Core, 0x40, 0x1234_5678).unwrap();
        assert_eq!(hal.read32(Window::Core, 0x40).unwrap(), 0x1234_5678);
        assert_eq!(hal.read32(Window::Dma, 0x40).unwrap(), 0);
        assert!(hal.read32(Window::Core, 0x1000).is_err());
        let mut a = hal.alloc_dma(100).unwrap();
        let b = hal.alloc_dma(100).unwrap();
        assert_eq!((a.phys(), b.phys()), (0x3f00_0000, 0x3f00_0080));
        a.bytes_mut()[0] = 7;
        hal.cache_clean(&mut a, 0, 100).unwrap();
        let dir = root.join("class/u-dma-buf/udmabuf0");
        assert_eq!(
            std::fs::read_to_string(dir.join("sync_size")).unwrap(),
            "100"
        );
        assert_eq!(
            std::fs::read_to_string(dir.join("sync_direction")).unwrap(),
            "1"
        );
        assert_eq!(
            std::fs::read_to_string(dir.join("sync_for_device")).unwrap(),
            "1"
        );
        let e = hal.alloc_dma(4000).err().unwrap().to_string();
        assert!(e.contains("do not fit"), "{e}");
        drop(hal);
        let _ = std::fs::remove_dir_all(&root);
    }
}
