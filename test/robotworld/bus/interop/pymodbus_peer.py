"""A Modbus RTU server made of pymodbus, over a raw TCP byte stream (as ser2net offers a serial line).

pymodbus does the Modbus part: its RTU framer and CRC, its request decoder, its data store, its device identity
(Read Device Identification, split into parts when the objects do not fit one response, and Report Server ID,
whose server ID is the identity's objects joined by "-", followed by the run indicator). This script only
carries bytes and plays the line: a reply delay, a byte-by-byte trickle, an adapter that echoes each request.

pymodbus's RTU framer takes every Diagnostics request as 8 bytes (one data word); Return Query Data may carry any
number of words, so those frames are cut where their CRC is right before pymodbus decodes them.

Prints "PORT <n>" once listening on 127.0.0.1, then serves until killed.
"""
import argparse
import asyncio
import logging
import sys

from pymodbus.datastore import ModbusDeviceContext, ModbusServerContext, ModbusSequentialDataBlock
from pymodbus.exceptions import NoSuchIdException
from pymodbus.framer import FramerRTU
from pymodbus.pdu import DecodePDU
from pymodbus.pdu.device import ModbusControlBlock, ModbusDeviceIdentification


def crc_ok(frame: bytes) -> bool:
    return len(frame) >= 4 and FramerRTU.check_CRC(frame[:-2], (frame[-2] << 8) | frame[-1])


class Peer:
    def __init__(self, args):
        self.args = args
        self.decoder = DecodePDU(True)
        self.framer = FramerRTU(DecodePDU(True))
        device = ModbusDeviceContext(di=ModbusSequentialDataBlock(1, [False] * 16),
                                     hr=ModbusSequentialDataBlock(1, [0] * 16))
        self.context = ModbusServerContext(devices={args.unit: device}, single=False)
        identity = ModbusDeviceIdentification(info_name={
            "VendorName": args.vendor, "ProductCode": args.product, "MajorMinorRevision": args.revision})
        ModbusControlBlock().Identity.update(identity)
        self.requests = 0

    def next_frame(self, buffer: bytes):
        """(frame length, or 0 when more bytes are needed, or -1 when the first byte is to be dropped)."""
        if len(buffer) >= 4 and buffer[1] == 0x08 and buffer[2] == 0 and buffer[3] == 0:
            for length in range(6, min(len(buffer), 256) + 1, 2):
                if crc_ok(buffer[:length]):
                    return length
            return -1 if len(buffer) > 256 else 0
        used, dev_id, _tid, pdu = self.framer.decode(buffer)
        if used == 0:
            return 0
        if not pdu:
            return -1
        return used

    async def reply(self, writer, frame: bytes):
        self.requests += 1
        if self.args.echo:
            writer.write(frame)  # the master's adapter hears its own request
            await writer.drain()
        dev_id = frame[0]
        pdu_bytes = frame[1:-2]
        if dev_id not in self.context.device_ids():
            return  # another module's address: silence, as on a bus (pymodbus itself would answer identity requests)
        try:
            request = self.decoder.decode(pdu_bytes)
            if request is None:
                return
            request.dev_id = dev_id
            response = await request.datastore_update(self.context, dev_id)
        except NoSuchIdException:
            return  # nobody at that address: silence, as on a bus
        payload = bytes([response.function_code]) + response.encode()
        answer = self.framer.encode(payload, dev_id, 0)
        await asyncio.sleep(self.args.delay_ms / 1000)
        if self.args.trickle_ms > 0:
            for byte in answer:
                writer.write(bytes([byte]))
                await writer.drain()
                await asyncio.sleep(self.args.trickle_ms / 1000)
        else:
            writer.write(answer)
            await writer.drain()

    async def serve(self, reader, writer):
        buffer = b""
        try:
            while True:
                chunk = await reader.read(512)
                if not chunk:
                    return
                buffer += chunk
                while buffer:
                    length = self.next_frame(buffer)
                    if length == 0:
                        break
                    if length < 0:
                        buffer = buffer[1:]
                        continue
                    frame, buffer = buffer[:length], buffer[length:]
                    if crc_ok(frame):
                        await self.reply(writer, frame)
        finally:
            writer.close()


async def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--unit", type=int, default=2)
    parser.add_argument("--vendor", default="pymodbus")
    parser.add_argument("--product", default="15B63B2")
    parser.add_argument("--revision", default="1.0")
    parser.add_argument("--delay-ms", type=float, default=0)
    parser.add_argument("--trickle-ms", type=float, default=0)
    parser.add_argument("--echo", action="store_true")
    args = parser.parse_args()
    logging.getLogger("pymodbus").setLevel(logging.ERROR)
    peer = Peer(args)
    server = await asyncio.start_server(peer.serve, "127.0.0.1", 0)
    print("PORT", server.sockets[0].getsockname()[1], flush=True)
    async with server:
        await server.serve_forever()


if __name__ == "__main__":
    try:
        asyncio.run(main())
    except KeyboardInterrupt:
        sys.exit(0)
