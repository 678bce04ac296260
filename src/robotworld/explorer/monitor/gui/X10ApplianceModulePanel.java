package robotworld.explorer.monitor.gui;

/** An X10 appliance module: on or off (thesis figure 4.8). */
public class X10ApplianceModulePanel extends ModulePanel {

    private final OnOffIndicator indicator = new OnOffIndicator();

    public X10ApplianceModulePanel(String moduleName) {
        super("X10ApplianceModule", moduleName);
        setBody(indicator);
    }

    /** Shows the appliance switched on or off. */
    public void showOn(boolean on) {
        indicator.showOn(on);
    }

    /** The state shown. */
    public OnOffIndicator indicator() {
        return indicator;
    }
}
