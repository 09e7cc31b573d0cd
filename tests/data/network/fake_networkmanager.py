#!/usr/bin/python3
"""A stand-in NetworkManager (for the tests of docs/network.md): the part of its D-Bus API azeltrack
reads (GetDevices; Device.Interface and DeviceType; Device.Wireless.ActiveAccessPoint; AccessPoint
Ssid and Strength), owned on the bus at argv[1]. Devices: eth0 (Ethernet), wlan0 associated
with "shack-net" at 72 %, wlan1 not associated.
Usage: /usr/bin/python3 fake_networkmanager.py BUS_ADDRESS  (python3-dbus, python3-gi)"""
import sys

import dbus
import dbus.mainloop.glib
import dbus.service
from gi.repository import GLib

NM = "org.freedesktop.NetworkManager"
DEVICE = NM + ".Device"
WIRELESS = DEVICE + ".Wireless"
AP = NM + ".AccessPoint"
ROOT = "/org/freedesktop/NetworkManager"

OBJECTS = {
    ROOT + "/Devices/1": {DEVICE: {"Interface": dbus.String("eth0"),
                                   "DeviceType": dbus.UInt32(1)}},
    ROOT + "/Devices/2": {DEVICE: {"Interface": dbus.String("wlan0"),
                                   "DeviceType": dbus.UInt32(2)},
                          WIRELESS: {"ActiveAccessPoint": dbus.ObjectPath(ROOT + "/AccessPoint/7")}},
    ROOT + "/Devices/3": {DEVICE: {"Interface": dbus.String("wlan1"),
                                   "DeviceType": dbus.UInt32(2)},
                          WIRELESS: {"ActiveAccessPoint": dbus.ObjectPath("/")}},
    ROOT + "/AccessPoint/7": {AP: {"Ssid": dbus.ByteArray(b"shack-net"), "Strength": dbus.Byte(72)}},
}


class Properties(dbus.service.Object):
    def __init__(self, bus, path, props):
        super().__init__(bus, path)
        self.props = props

    @dbus.service.method("org.freedesktop.DBus.Properties", in_signature="ss", out_signature="v")
    def Get(self, interface, name):  # pylint: disable=invalid-name
        try:
            return self.props[interface][name]
        except KeyError as e:
            raise dbus.exceptions.DBusException("no such property",
                                                name="org.freedesktop.DBus.Error.UnknownProperty") from e


class Manager(dbus.service.Object):
    @dbus.service.method(NM, out_signature="ao")
    def GetDevices(self):  # pylint: disable=invalid-name
        return [dbus.ObjectPath(p) for p in sorted(OBJECTS) if "/Devices/" in p]


def main():
    dbus.mainloop.glib.DBusGMainLoop(set_as_default=True)
    bus = dbus.bus.BusConnection(sys.argv[1])
    keep = [Manager(bus, ROOT)] + [Properties(bus, p, v) for p, v in OBJECTS.items()]
    name = dbus.service.BusName(NM, bus)  # last: clients see the name once everything is there
    print("ready", flush=True)
    GLib.MainLoop().run()
    del keep, name


if __name__ == "__main__":
    main()
