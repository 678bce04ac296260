package robotworld.sim.robot;

import java.io.ByteArrayOutputStream;
import java.nio.charset.StandardCharsets;
import robotworld.bus.modbus.ExceptionCodes;
import robotworld.bus.modbus.FunctionCodes;

/**
 * The server side of the Modbus functions a module answers: read discrete inputs / input registers / holding
 * registers, write single / multiple registers, diagnostics echo, report server ID and read device
 * identification. Anything else is refused with "illegal function". Written from the Modbus application protocol
 * specification, independently of the client code in {@code robotworld.bus}.
 */
final class RequestHandler {

    private RequestHandler() {
    }

    /** The response PDU to {@code request}, addressed to {@code module}; an exception response when refused. */
    static byte[] respond(SimModule module, byte[] request) {
        int function = request[0] & 0xFF;
        try {
            if (module.faults().refusal() != 0) {
                throw new ModbusRefusal(module.faults().refusal(), "fault injection");
            }
            return switch (function) {
                case FunctionCodes.READ_DISCRETE_INPUTS -> readBits(module, request);
                case FunctionCodes.READ_INPUT_REGISTERS -> readRegisters(request, module.inputRegisterCount(),
                        module::inputRegister);
                case FunctionCodes.READ_HOLDING_REGISTERS -> readRegisters(request, module.holdingRegisterCount(),
                        module::holdingRegister);
                case FunctionCodes.WRITE_SINGLE_REGISTER -> writeSingle(module, request);
                case FunctionCodes.WRITE_MULTIPLE_REGISTERS -> writeMultiple(module, request);
                case FunctionCodes.DIAGNOSTICS -> diagnostics(request);
                case FunctionCodes.REPORT_SERVER_ID -> reportServerId(module, request);
                case FunctionCodes.ENCAPSULATED_INTERFACE -> deviceIdentification(module, request);
                default -> throw new ModbusRefusal(ExceptionCodes.ILLEGAL_FUNCTION, "unsupported function");
            };
        } catch (ModbusRefusal refusal) {
            return new byte[] {(byte) (function | FunctionCodes.EXCEPTION_BIT), (byte) refusal.exceptionCode()};
        }
    }

    /** Applies a broadcast (address 0) write; broadcasts are never answered. */
    static void applyBroadcast(SimModule module, byte[] request) {
        int function = request[0] & 0xFF;
        if (function == FunctionCodes.WRITE_SINGLE_REGISTER || function == FunctionCodes.WRITE_MULTIPLE_REGISTERS) {
            respond(module, request);
        }
    }

    private interface Registers {
        int get(int index);
    }

    private static byte[] readBits(SimModule module, byte[] request) throws ModbusRefusal {
        requireLength(request, 5);
        int first = word(request, 1);
        int count = word(request, 3);
        if (count < 1 || count > 2000) {
            throw new ModbusRefusal(ExceptionCodes.ILLEGAL_DATA_VALUE, "count " + count);
        }
        requireRange(first, count, module.discreteInputCount());
        byte[] response = new byte[2 + (count + 7) / 8];
        response[0] = request[0];
        response[1] = (byte) ((count + 7) / 8);
        for (int i = 0; i < count; i++) {
            if (module.discreteInput(first + i)) {
                response[2 + i / 8] |= (byte) (1 << (i % 8));
            }
        }
        return response;
    }

    private static byte[] readRegisters(byte[] request, int available, Registers registers) throws ModbusRefusal {
        requireLength(request, 5);
        int first = word(request, 1);
        int count = word(request, 3);
        if (count < 1 || count > 125) {
            throw new ModbusRefusal(ExceptionCodes.ILLEGAL_DATA_VALUE, "count " + count);
        }
        requireRange(first, count, available);
        byte[] response = new byte[2 + 2 * count];
        response[0] = request[0];
        response[1] = (byte) (2 * count);
        for (int i = 0; i < count; i++) {
            int value = registers.get(first + i);
            response[2 + 2 * i] = (byte) (value >>> 8);
            response[3 + 2 * i] = (byte) value;
        }
        return response;
    }

    private static byte[] writeSingle(SimModule module, byte[] request) throws ModbusRefusal {
        requireLength(request, 5);
        int register = word(request, 1);
        requireRange(register, 1, module.holdingRegisterCount());
        module.writeHoldingRegister(register, word(request, 3));
        return request.clone();
    }

    private static byte[] writeMultiple(SimModule module, byte[] request) throws ModbusRefusal {
        if (request.length < 6) {
            throw new ModbusRefusal(ExceptionCodes.ILLEGAL_DATA_VALUE, "short request");
        }
        int first = word(request, 1);
        int count = word(request, 3);
        int bytes = request[5] & 0xFF;
        if (count < 1 || count > 123 || bytes != 2 * count || request.length != 6 + bytes) {
            throw new ModbusRefusal(ExceptionCodes.ILLEGAL_DATA_VALUE, "count " + count + ", bytes " + bytes);
        }
        requireRange(first, count, module.holdingRegisterCount());
        for (int i = 0; i < count; i++) {
            module.writeHoldingRegister(first + i, word(request, 6 + 2 * i));
        }
        return new byte[] {request[0], request[1], request[2], request[3], request[4]};
    }

    /** Return Query Data: the request comes back unaltered, whatever number of data words it carries. */
    private static byte[] diagnostics(byte[] request) throws ModbusRefusal {
        if (request.length < 3 || (request.length - 3) % 2 != 0) {
            throw new ModbusRefusal(ExceptionCodes.ILLEGAL_DATA_VALUE, "request of " + request.length + " bytes");
        }
        if (word(request, 1) != FunctionCodes.DIAGNOSTICS_RETURN_QUERY_DATA) {
            throw new ModbusRefusal(ExceptionCodes.ILLEGAL_FUNCTION, "only Return Query Data is supported");
        }
        return request.clone();
    }

    /**
     * Server ID, then the run indicator as the last byte, no additional data: a client that takes the indicator
     * from right after a one-byte ID (libmodbus) and one that takes it from the end (pymodbus) both read this
     * layout right. The server ID is the address, or the configured ASCII ID of any length.
     */
    private static byte[] reportServerId(SimModule module, byte[] request) throws ModbusRefusal {
        requireLength(request, 1);
        String configured = module.identity().serverId();
        byte[] serverId = configured.isEmpty() ? new byte[] {(byte) module.address()} : ascii(configured);
        byte[] response = new byte[3 + serverId.length];
        response[0] = (byte) FunctionCodes.REPORT_SERVER_ID;
        response[1] = (byte) (serverId.length + 1);
        System.arraycopy(serverId, 0, response, 2, serverId.length);
        response[response.length - 1] = (byte) (module.faults().isStopped() ? 0x00 : 0xFF);
        return response;
    }

    private static byte[] deviceIdentification(SimModule module, byte[] request) throws ModbusRefusal {
        requireLength(request, 4);
        if ((request[1] & 0xFF) != FunctionCodes.MEI_READ_DEVICE_ID) {
            throw new ModbusRefusal(ExceptionCodes.ILLEGAL_FUNCTION, "unsupported MEI type");
        }
        int code = request[2] & 0xFF;
        int objectId = request[3] & 0xFF;
        if (code < 1 || code > 4) {
            throw new ModbusRefusal(ExceptionCodes.ILLEGAL_DATA_VALUE, "read device id code " + code);
        }
        String[] objects = {module.identity().vendorName(), module.identity().nodeId(), module.identity().version()};
        if (code == 4 && objectId >= objects.length) {
            throw new ModbusRefusal(ExceptionCodes.ILLEGAL_DATA_ADDRESS, "object " + objectId);
        }
        // only the basic category exists: a request for a later object starts over at 0, as the spec allows
        int firstObject = objectId < objects.length ? objectId : 0;
        int lastObject = code == 4 ? objectId : objects.length - 1;
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        out.write(FunctionCodes.ENCAPSULATED_INTERFACE);
        out.write(FunctionCodes.MEI_READ_DEVICE_ID);
        out.write(code);
        out.write(0x01); // conformity level: basic identification, stream access only
        out.write(0x00); // no more follows
        out.write(0x00); // next object id
        out.write(lastObject - firstObject + 1);
        for (int id = firstObject; id <= lastObject; id++) {
            byte[] value = ascii(objects[id]);
            out.write(id);
            out.write(value.length);
            out.writeBytes(value);
        }
        return out.toByteArray();
    }

    private static void requireLength(byte[] request, int length) throws ModbusRefusal {
        if (request.length != length) {
            throw new ModbusRefusal(ExceptionCodes.ILLEGAL_DATA_VALUE, "request of " + request.length + " bytes");
        }
    }

    private static void requireRange(int first, int count, int available) throws ModbusRefusal {
        if (first + count > available) {
            throw new ModbusRefusal(ExceptionCodes.ILLEGAL_DATA_ADDRESS, first + "+" + count + " beyond " + available);
        }
    }

    private static int word(byte[] bytes, int at) {
        return (bytes[at] & 0xFF) << 8 | bytes[at + 1] & 0xFF;
    }

    private static byte[] ascii(String text) {
        byte[] bytes = text.getBytes(StandardCharsets.US_ASCII);
        return bytes.length > 64 ? java.util.Arrays.copyOf(bytes, 64) : bytes;
    }
}
