//! I/O devices (units) and networks (buses) as controller state (manual §1.9 "禁用和启用
//! I/O模块", "获取 I/O 网络和设备状态"): which device each signal lives on, whether a device
//! is enabled, and which networks exist.
//!
//! Simulated devices and networks never fail: a device is running unless a program (or
//! the configuration) disabled it, and every network runs. A signal on a disabled device
//! cannot be read or written (ERR_NORUNUNIT); a signal without a device is virtual and
//! always reachable.

use std::collections::HashMap;
use std::fmt;

/// One I/O device (RobotWare 6) or unit (RobotWare 5) of the configuration.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct DeviceDef {
    pub name: String,
    /// The network (bus) it is connected to, if the configuration names one.
    pub network: Option<String>,
    /// Whether the device is enabled at start-up.
    pub enabled: bool,
}

impl DeviceDef {
    /// An enabled device on `network`.
    pub fn new(name: &str, network: Option<&str>) -> DeviceDef {
        DeviceDef { name: name.to_string(), network: network.map(str::to_string), enabled: true }
    }
}

/// The network every controller has for its internal devices.
// uncertain: RobotWare 6 calls it `Local`; RobotWare 5's `Virtual1` is not added.
pub const LOCAL_NETWORK: &str = "Local";

/// Why a device or network request failed.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum UnitError {
    /// No device (or network) of this name is configured.
    UnknownDevice(String),
    UnknownNetwork(String),
    /// Two devices or two networks with the same name (a load error).
    Duplicate(String),
    /// A signal names a device that is not configured (a load error).
    SignalDevice {
        signal: String,
        device: String,
    },
}

impl fmt::Display for UnitError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            UnitError::UnknownDevice(name) => write!(f, "no I/O device `{name}` is configured"),
            UnitError::UnknownNetwork(name) => write!(f, "no I/O network `{name}` is configured"),
            UnitError::Duplicate(name) => write!(f, "`{name}` is configured more than once"),
            UnitError::SignalDevice { signal, device } => {
                write!(f, "signal `{signal}` is on device `{device}`, which is not configured")
            }
        }
    }
}

impl std::error::Error for UnitError {}

/// A stimulus order whose signal id has this bit set connects (value 1) or
/// disconnects (value 0) the device whose index is in the other bits.
pub const DEVICE_EVENT: u32 = 1 << 30;

/// The devices and networks of one controller and the device of every signal.
#[derive(Debug, Clone, Default)]
pub struct Units {
    devices: Vec<DeviceDef>,
    by_name: HashMap<String, usize>,
    enabled: Vec<bool>,
    /// Whether each device answers on its network (a stimulus disconnects and
    /// reconnects it, as a tool changer does).
    connected: Vec<bool>,
    networks: Vec<String>,
    /// By signal id: the index of its device, `None` for a virtual signal.
    signal_device: Vec<Option<usize>>,
}

impl Units {
    /// Devices and networks; `signal_devices` gives each signal's device name in signal id
    /// order. Networks named by devices but not listed are added, as is [`LOCAL_NETWORK`].
    pub fn new(
        devices: Vec<DeviceDef>,
        networks: Vec<String>,
        signal_devices: &[(String, Option<String>)],
    ) -> Result<Units, UnitError> {
        let mut by_name = HashMap::new();
        for (index, device) in devices.iter().enumerate() {
            if by_name.insert(device.name.to_ascii_lowercase(), index).is_some() {
                return Err(UnitError::Duplicate(device.name.clone()));
            }
        }
        let mut units = Units {
            enabled: devices.iter().map(|d| d.enabled).collect(),
            connected: vec![true; devices.len()],
            by_name,
            ..Units::default()
        };
        for name in networks {
            if units.network_index(&name).is_some() {
                return Err(UnitError::Duplicate(name));
            }
            units.networks.push(name);
        }
        let implied = devices.iter().filter_map(|d| d.network.clone()).chain([LOCAL_NETWORK.to_string()]);
        for name in implied {
            if units.network_index(&name).is_none() {
                units.networks.push(name);
            }
        }
        units.devices = devices;
        for (signal, device) in signal_devices {
            let index = match device {
                None => None,
                Some(name) => match units.device_index(name) {
                    Some(index) => Some(index),
                    None => return Err(UnitError::SignalDevice { signal: signal.clone(), device: name.clone() }),
                },
            };
            units.signal_device.push(index);
        }
        Ok(units)
    }

    fn device_index(&self, name: &str) -> Option<usize> {
        self.by_name.get(&name.to_ascii_lowercase()).copied()
    }

    fn network_index(&self, name: &str) -> Option<usize> {
        self.networks.iter().position(|n| n.eq_ignore_ascii_case(name))
    }

    /// Every configured device.
    pub fn devices(&self) -> &[DeviceDef] {
        &self.devices
    }

    /// Every network (configured, named by a device, and [`LOCAL_NETWORK`]).
    pub fn networks(&self) -> &[String] {
        &self.networks
    }

    pub fn device(&self, name: &str) -> Option<&DeviceDef> {
        self.device_index(name).map(|i| &self.devices[i])
    }

    /// Whether device `name` is enabled (logically and, simulated, physically running).
    pub fn is_enabled(&self, name: &str) -> Result<bool, UnitError> {
        let index = self.device_index(name).ok_or_else(|| UnitError::UnknownDevice(name.to_string()))?;
        Ok(self.enabled[index])
    }

    /// Enables or disables device `name`.
    pub fn set_enabled(&mut self, name: &str, enabled: bool) -> Result<(), UnitError> {
        let index = self.device_index(name).ok_or_else(|| UnitError::UnknownDevice(name.to_string()))?;
        self.enabled[index] = enabled;
        Ok(())
    }

    /// Whether device `name` answers on its network.
    pub fn is_connected(&self, name: &str) -> Result<bool, UnitError> {
        let index = self.device_index(name).ok_or_else(|| UnitError::UnknownDevice(name.to_string()))?;
        Ok(self.connected[index])
    }

    /// The index of device `name` (stimulus orders name a device by it).
    pub fn index_of(&self, name: &str) -> Option<usize> {
        self.device_index(name)
    }

    /// Connects or disconnects the device at `index`; its name when there is one.
    pub fn set_connected(&mut self, index: usize, connected: bool) -> Option<&str> {
        *self.connected.get_mut(index)? = connected;
        self.devices.get(index).map(|d| d.name.as_str())
    }

    /// Whether network `name` exists (every existing network runs).
    pub fn has_network(&self, name: &str) -> bool {
        self.network_index(name).is_some()
    }

    /// The device a signal is on (`None`: virtual, or no device information).
    pub fn signal_device(&self, id: u32) -> Option<&DeviceDef> {
        let index = (*self.signal_device.get(id as usize)?)?;
        self.devices.get(index)
    }

    /// Whether a signal can be reached: virtual, or on an enabled device that answers.
    pub fn signal_running(&self, id: u32) -> bool {
        match self.signal_device.get(id as usize).copied().flatten() {
            None => true,
            Some(index) => {
                self.enabled.get(index).copied().unwrap_or(true) && self.connected.get(index).copied().unwrap_or(true)
            }
        }
    }

    /// The signal ids on device `name`.
    pub fn signals_of(&self, name: &str) -> Vec<u32> {
        let Some(index) = self.device_index(name) else { return Vec::new() };
        (0..self.signal_device.len() as u32).filter(|&id| self.signal_device[id as usize] == Some(index)).collect()
    }
}
