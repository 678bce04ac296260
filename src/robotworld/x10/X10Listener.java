package robotworld.x10;

/**
 * Receives what the CM11A uploads from the power line (remote controls, motion sensors, other controllers).
 * Called on the controller's event thread, one event at a time in arrival order; it may call the controller.
 */
@FunctionalInterface
public interface X10Listener {

    /** One decoded power-line event. */
    void onEvent(X10Event event);
}
