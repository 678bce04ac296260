package robotworld.explorer.monitor.gui;

import java.awt.BorderLayout;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JSlider;

/**
 * An X10 lamp module: on/off and the brightness on a 0..100 % slider (thesis figure 4.9). The level is an
 * estimate (see {@link robotworld.explorer.monitor.LampLevel}): X10 only sends relative dim and bright commands.
 */
public class X10LampModulePanel extends ModulePanel {

    private final OnOffIndicator indicator = new OnOffIndicator();
    private final JSlider slider = new JSlider(0, 100, 0);
    private final JLabel levelText = new JLabel("level unknown");

    public X10LampModulePanel(String moduleName) {
        super("X10LampModule", moduleName);
        slider.setMajorTickSpacing(20);
        slider.setPaintTicks(true);
        slider.setPaintLabels(true);
        slider.setEnabled(false); // it shows, it does not control
        slider.getAccessibleContext().setAccessibleName("brightness in percent (estimated)");
        JPanel body = new JPanel(new BorderLayout());
        body.add(slider, BorderLayout.CENTER);
        JPanel row = new JPanel(new BorderLayout());
        row.add(indicator, BorderLayout.WEST);
        row.add(levelText, BorderLayout.EAST);
        body.add(row, BorderLayout.SOUTH);
        setBody(body);
    }

    /** Shows the lamp's state and its estimated brightness in percent. */
    public void showLamp(boolean on, int levelPercent) {
        indicator.showOn(on);
        slider.setValue(on ? levelPercent : 0);
        levelText.setText(on ? "level ≈ " + levelPercent + " %" : "off (level ≈ " + levelPercent + " % when on)");
    }

    /** The on/off state shown. */
    public OnOffIndicator indicator() {
        return indicator;
    }

    /** The slider's value: the estimated brightness, 0 when off. */
    public int sliderValue() {
        return slider.getValue();
    }
}
