package robotworld.x10;

/**
 * The CM11A did not answer within the configured time: a dead, unplugged or powered-off interface, or a wrong
 * port. The message names the port, the frame and the step that timed out.
 */
public class X10TimeoutException extends X10Exception {

    public X10TimeoutException(String portName, String message) {
        super(portName, message);
    }
}
