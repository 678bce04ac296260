package robotworld.explorer.monitor.gui;

import javax.swing.JTextArea;

/** Stands where a module's monitor would be when its class is missing or broken, and says which class and why. */
public class PlaceholderPanel extends ModulePanel {

    private final String text;

    public PlaceholderPanel(String moduleClass, String moduleName, String className, String reason) {
        super(moduleClass, moduleName);
        this.text = "Not monitored: no usable monitor class " + className + " (" + reason + ").";
        JTextArea message = new JTextArea(text, 2, 40);
        message.setEditable(false);
        message.setLineWrap(true);
        message.setWrapStyleWord(true);
        message.setOpaque(false);
        message.getAccessibleContext().setAccessibleName("why this module is not monitored");
        setBody(message);
    }

    /** What the panel says. */
    public String message() {
        return text;
    }
}
