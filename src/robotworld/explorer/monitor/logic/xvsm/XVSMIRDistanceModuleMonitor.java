package robotworld.explorer.monitor.logic.xvsm;

import robotworld.explorer.monitor.MonitoredModule;
import robotworld.explorer.monitor.gui.IRDistanceModulePanel;
import robotworld.observe.WorldTap;
import robotworld.space.Capi;
import robotworld.space.Tuple;
import robotworld.xvsm.CallTuple;

/**
 * Answers of an IR distance module (thesis table 8): a text of seven distances ({@code getAllSensors}), a tuple
 * of seven raw readings ({@code getAllSensors_ByteRep}), or {@code <sensorNr, mm>} for one sensor.
 */
public class XVSMIRDistanceModuleMonitor extends XVSMMonitor<IRDistanceModulePanel> {

    public XVSMIRDistanceModuleMonitor(MonitoredModule module, Capi space) {
        super(module, space, new IRDistanceModulePanel(module.moduleName()));
    }

    /** Watches through a tap shared with the other monitors of the world. */
    public XVSMIRDistanceModuleMonitor(MonitoredModule module, WorldTap tap) {
        super(module, tap, new IRDistanceModulePanel(module.moduleName()));
    }

    @Override
    protected void show(CallTuple answer, IRDistanceModulePanel panel) {
        answer.expectFields(1);
        switch (answer.functionText()) {
            case "getAllSensors" -> panel.showDistances(numbers(answer.stringAt(0)));
            case "getAllSensors_ByteRep" -> panel.showRawReadings(numbers(answer.tupleAt(0)));
            case "getSingleSensor", "getSingleSensor_Cached" -> {
                Tuple pair = answer.tupleAt(0);
                panel.showDistance((int) pair.longAt(0), (int) pair.longAt(1));
            }
            default -> throw answer.unknownFunction();
        }
    }

    private static int[] numbers(String text) {
        String[] parts = text.strip().split("\\s+");
        int[] values = new int[parts.length];
        for (int i = 0; i < parts.length; i++) {
            values[i] = Integer.parseInt(parts[i]);
        }
        return values;
    }

    private static int[] numbers(Tuple tuple) {
        int[] values = new int[tuple.arity()];
        for (int i = 0; i < values.length; i++) {
            values[i] = (int) tuple.longAt(i);
        }
        return values;
    }
}
